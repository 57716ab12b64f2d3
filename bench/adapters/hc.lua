--- HC (vrld/HC), through its public shape API: shapes.newPolygonShape / newCircleShape
--- and shape:collidesWith (GJK + EPA). Loaded from $STRIKE_PEERS/HC; never committed.
local root = ...
local W = require('bench.workloads')
local A = { name = 'HC' }

function A.load(peers)
  package.path = peers .. '/?.lua;' .. peers .. '/?/init.lua;' .. package.path
  -- HC calls the global unpack, which Lua 5.2+ no longer have; this process only.
  rawset(_G, 'unpack', rawget(_G, 'unpack') or table.unpack) -- luacheck: ignore 143
  local ok, shapes = pcall(require, 'HC.shapes')
  if not ok then return nil, shapes end
  A.shapes = shapes
  return true
end

local unpack = table.unpack or unpack -- luacheck: ignore 113 143

local function build(d)
  if d.kind == 'circle' then return A.shapes.newCircleShape(d.x, d.y, d.r) end
  if d.kind == 'rect' or d.kind == 'ngon' then return A.shapes.newPolygonShape(unpack(W.vertices(d, true))) end
  return nil -- HC has no segment and no compound of convex shapes
end

A.methods = {
  {
    name = 'collidesWith',
    build = build,
    test = function(a, b)
      local hit, dx, dy = a:collidesWith(b)
      if not hit then return false, 0 end
      return true, math.sqrt(dx * dx + dy * dy)
    end,
  },
}

A.transform = {
  build = build,
  step = function(s)
    s:move(0.5, -0.25)
    s:rotate(0.01)
    return s:bbox()
  end,
}

return A, root
