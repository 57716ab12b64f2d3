--- slick (erinmaus/slick) for bench/movers.lua, through its public API (README, "slick.world"):
--- slick.newWorld over the square with a 128 px margin (the border walls inside its quad tree),
--- every wall and mover an entity at its centre with slick.newRectangleShape(-w / 2, -h / 2, w,
--- h) (a capsule as its w x h bounding box), each mover moved with world:move(item, goalX,
--- goalY, nil, query) (no filter: slick's default 'slide'; one slick.newWorldQuery reused by
--- every move). The collisions counted are `#query.results`. Runs with the JIT off on LuaJIT
--- (A.jitOff; see bench/adapters/move_slick.lua). Loaded by move_slick.lua from
--- $STRIKE_PEERS/slick; never committed. Same methods as movers_strike.lua.
local loader = require('bench.adapters.move_slick')

local A = { name = 'slick', note = 'slick.newWorld(), world:move(item, goalX, goalY, nil, query) with a reused query '
  .. '(a capsule is its bounding box)', jitOff = true, load = loader.load }

local MARGIN = 128

function A.new(w)
  local slick = loader.lib
  local side = w.side
  local world = slick.newWorld(side + 2 * MARGIN, side + 2 * MARGIN, { quadTreeX = -MARGIN, quadTreeY = -MARGIN })
  for k = 1, #w.wx do
    world:add({ wall = k }, w.wx[k], w.wy[k], slick.newRectangleShape(-w.ww[k] / 2, -w.wh[k] / 2, w.ww[k], w.wh[k]))
  end
  local items = {}
  for i = 1, w.n do
    items[i] = { mover = i }
    world:add(items[i], w.x[i], w.y[i], slick.newRectangleShape(-w.w[i] / 2, -w.h[i] / 2, w.w[i], w.h[i]))
  end
  local query = slick.newWorldQuery(world)
  return {
    move = function(i, gx, gy)
      local ax, ay = world:move(items[i], gx, gy, nil, query)
      return ax, ay, #query.results
    end,
  }
end

return A
