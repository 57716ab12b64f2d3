--- slick (erinmaus/slick), through its public world API. Loaded from $STRIKE_PEERS/slick;
--- never committed.
---
--- slick has no public pairwise shape test: its collision modules are internal ("anything
--- not exposed directly by importing slick is considered private", README). What a slick user
--- does for "does A overlap B, and by how much" is a world query, so each pair becomes a
--- two-entity world (built before timing, sharing one slick.newCache so that worlds do not
--- each build a triangulator), and the timed call is
---   world:test(itemA, x, y, nil, query)
--- with A at its own position and a re-used slick.newWorldQuery (the README's garbage-saving
--- usage). A hit is any response; the separation is the largest response.depth. test is
--- world:project without motion, the cheapest of project / check / move (check and move also
--- run collision responses). Shapes: rectangles and regular polygons are
--- newRectangleShape / newPolygonShape placed by slick.newTransform(x, y, angle); circles are
--- newCircleShape (slick turns them into polygons); segments newLineSegmentShape; compound
--- bodies newShapeGroup of the parts.
---
--- Verdicts: slick's circles are inscribed polygons, so it misses the shallowest circle
--- overlaps (a few tenths of a pixel); the runner counts those as wrong verdicts.
--- No transforms row: moving and turning an entity is world:update, which also re-files it
--- in the quadtree, and an entity's bounds are not public.
---
--- slick sets up its modules with setfenv, so it only loads on Lua 5.1 and LuaJIT. On
--- LuaJIT 2.1 its world:move has been seen to crash with the JIT on, so the method runs with
--- the JIT off there (the runner flushes and turns it off for the row) and says so.
local A = { name = 'slick' }

local jit = rawget(_G, 'jit')
local W = require('bench.workloads')
local slick, cache

function A.load(peers, folder)
  if not rawget(_G, 'setfenv') then
    return nil, 'slick needs setfenv (Lua 5.1 / LuaJIT only) on ' .. _VERSION
  end
  local root = peers .. '/' .. folder
  package.path = root .. '/?.lua;' .. root .. '/?/init.lua;' .. package.path
  local ok, lib = pcall(require, 'slick')
  if not ok then return nil, lib end
  slick = lib
  cache = slick.newCache({})
  return true
end

local unpack = table.unpack or unpack -- luacheck: ignore 113 143

-- A body: a shape definition and the transform of the entity that carries it.
local function build(d)
  local k = d.kind
  if k == 'rect' then
    return { shape = slick.newRectangleShape(-d.w / 2, -d.h / 2, d.w, d.h), x = d.x, y = d.y, angle = d.angle }
  elseif k == 'ngon' then
    return { shape = slick.newPolygonShape(W.vertices(d)), x = d.x, y = d.y, angle = d.angle }
  elseif k == 'circle' then
    return { shape = slick.newCircleShape(0, 0, d.r), x = d.x, y = d.y, angle = 0 }
  elseif k == 'edge' then
    local cx, cy = (d.x1 + d.x2) / 2, (d.y1 + d.y2) / 2
    return { shape = slick.newLineSegmentShape(d.x1 - cx, d.y1 - cy, d.x2 - cx, d.y2 - cy), x = cx, y = cy, angle = 0 }
  elseif k == 'compound' then
    -- The parts in the body's frame; the entity sits at the origin.
    local parts = {}
    for i, p in ipairs(d.parts) do
      if p.kind == 'circle' then
        parts[i] = slick.newCircleShape(p.x, p.y, p.r)
      else
        parts[i] = slick.newPolygonShape(W.vertices(p, true))
      end
    end
    return { shape = slick.newShapeGroup(unpack(parts)), x = 0, y = 0, angle = 0 }
  end
end

-- A two-entity world per pair; the test queries A against it.
local function pair(a, b)
  local world = slick.newWorld(400, 400, { quadTreeX = -200, quadTreeY = -200, sharedCache = cache })
  world:add(a, slick.newTransform(a.x, a.y, a.angle), a.shape)
  world:add(b, slick.newTransform(b.x, b.y, b.angle), b.shape)
  local ctx = { world = world, item = a, x = a.x, y = a.y, query = slick.newWorldQuery(world) }
  return ctx, ctx
end

A.methods = {
  {
    name = jit and 'world:test (JIT off)' or 'world:test',
    jitOff = jit and true or nil,
    build = build,
    pair = pair,
    test = function(ctx)
      local results, n = ctx.world:test(ctx.item, ctx.x, ctx.y, nil, ctx.query)
      if n == 0 then return false, 0 end
      local depth = 0
      for i = 1, n do
        local r = results[i].depth
        if r > depth then depth = r end
      end
      return true, depth
    end,
  },
}

return A
