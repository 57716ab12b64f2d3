--- bump.lua (kikito/bump.lua) for bench/movers.lua, through its public API: bump.newWorld()
--- (its default 64 px cells), the walls and the movers added with world:add at their top-left
--- corners (a capsule as its w x h bounding box: bump has boxes only), each mover moved with
--- world:move(item, goalX, goalY) (no filter: bump's default 'slide'); centres turned into
--- corners on the way in and back on the way out. Loaded by bench/adapters/move_bump.lua from
--- $STRIKE_PEERS/bump.lua; never committed. Same methods as movers_strike.lua.
local loader = require('bench.adapters.move_bump')

local A = { name = 'bump', note = 'bump.newWorld() (64 px cells), world:move(item, goalX, goalY) (AABBs: a capsule '
  .. 'is its bounding box)', load = loader.load }

function A.new(w)
  local world = loader.lib.newWorld()
  for k = 1, #w.wx do
    world:add({ wall = k }, w.wx[k] - w.ww[k] / 2, w.wy[k] - w.wh[k] / 2, w.ww[k], w.wh[k])
  end
  local items, hw, hh = {}, {}, {}
  for i = 1, w.n do
    hw[i], hh[i] = w.w[i] / 2, w.h[i] / 2
    items[i] = { mover = i }
    world:add(items[i], w.x[i] - hw[i], w.y[i] - hh[i], w.w[i], w.h[i])
  end
  return {
    move = function(i, gx, gy)
      local x, y = hw[i], hh[i]
      local ax, ay, _, n = world:move(items[i], gx - x, gy - y)
      return ax + x, ay + y, n
    end,
  }
end

return A
