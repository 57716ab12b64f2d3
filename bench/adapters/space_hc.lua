--- HC (vrld/HC) as a world, for bench/space.lua, through its public API: HC.new(100) (its
--- spatial hash of 100 px cells), shapes registered with it, moved with moveTo, and
--- `collisions(shape)` per body (HC has no all-pairs query: each pair is found from both
--- sides, so the pair count is the sum over bodies, halved). Rays: HC's `raycast`.
--- Loaded from $STRIKE_PEERS/HC; never committed. Same methods as space_strike.lua.
local SW = require('bench.spaceworld')

local A = { name = 'HC', note = 'HC.new(100), moveTo, collisions(shape) per body' }

local HC, shapes
local unpack = table.unpack or unpack -- luacheck: ignore 113 143

function A.load(peers)
  package.path = peers .. '/?.lua;' .. peers .. '/?/init.lua;' .. package.path
  -- HC calls the global unpack, which Lua 5.2+ no longer have; this process only.
  rawset(_G, 'unpack', rawget(_G, 'unpack') or table.unpack) -- luacheck: ignore 143
  local ok, lib = pcall(require, 'HC')
  if not ok then return nil, lib end
  local ok2, sh = pcall(require, 'HC.shapes')
  if not ok2 then return nil, sh end
  HC, shapes = lib, sh
  return true
end

function A.new()
  return { hc = HC.new(100), bodies = {}, index = {} }
end

function A.make(w, i)
  local k, x, y = w.kind[i], w.x[i], w.y[i]
  if k == SW.BOX then
    local hw, hh = w.w[i] / 2, w.h[i] / 2
    return shapes.newPolygonShape(x - hw, y - hh, x + hw, y - hh, x + hw, y + hh, x - hw, y + hh)
  end
  if k == SW.POLYGON then return shapes.newPolygonShape(unpack(SW.vertices(w, i, x, y))) end
  return shapes.newCircleShape(x, y, w.r[i])
end

function A.add(st, body, i)
  st.hc:register(body)
  st.bodies[i], st.index[body] = body, i
end

function A.build(w)
  local st = A.new()
  for i = 1, w.n do A.add(st, A.make(w, i), i) end
  return st
end

function A.move(st, w)
  local bodies, x, y = st.bodies, w.x, w.y
  for i = 1, w.n do bodies[i]:moveTo(x[i], y[i]) end
end

function A.collide(st)
  local hc, bodies, count = st.hc, st.bodies, 0
  for i = 1, #bodies do
    for _ in pairs(hc:collisions(bodies[i])) do count = count + 1 end
  end
  return count / 2
end

function A.bullet(x, y)
  return shapes.newCircleShape(x, y, 2)
end

function A.remove(st, body)
  st.hc:remove(body)
  st.index[body] = nil
end

-- HC:raycast(x, y, dx, dy, range) gives { [shape] = { [k] = {x =, y =} or nil } }: the
-- crossings at ray parameters 0..range (dx, dy is a unit vector here, so a parameter is a
-- distance). The closest: the least distance from the origin over every point.
local sqrt = math.sqrt
function A.ray(st, x, y, dx, dy, len)
  local best, bestD = nil, math.huge
  for shape, pts in pairs(st.hc:raycast(x, y, dx, dy, len)) do
    for _, p in pairs(pts) do
      local d = sqrt((p.x - x) ^ 2 + (p.y - y) ^ 2)
      local i = st.index[shape]
      if d < bestD or (d == bestD and i < best) then best, bestD = i, d end
    end
  end
  if best then return best, bestD end
  return nil
end

return A
