--- bump.lua (kikito/bump.lua), through its public world API. Loaded from
--- $STRIKE_PEERS/bump.lua; never committed.
---
--- bump only knows axis-aligned rectangles, so it runs the 'aabb' workload alone (build
--- gives nil for anything else, and the runner skips the row). It has no public pairwise
--- test: the bump.rect helpers are "not part of the official API" (README). The cheapest
--- public query giving overlap and separation is
---   world:project(itemA, x, y, w, h, x, y)
--- ("could be also used as a query method", README): A's own rectangle, not moving, against
--- a two-item world (built per pair before timing). With no motion, bump reports only
--- overlaps, as col.overlaps with col.touch at the minimum displacement along one axis, so
--- the separation is |touch - (x, y)|. (world:check does the same projection and then runs
--- a collision response, so it is dearer.) Verdicts use bump's own strict overlap test.
--- No transforms row: bump's items never rotate.
local A = { name = 'bump' }

local bump

function A.load(peers, folder)
  local path = peers .. '/' .. folder .. '/bump.lua'
  local chunk, err = loadfile(path)
  if not chunk then return nil, err end
  local ok, lib = pcall(chunk, 'bump')
  if not ok then return nil, lib end
  if type(lib) ~= 'table' or not lib.newWorld then return nil, path .. ' did not return bump' end
  bump = lib
  return true
end

-- An item: bump keeps rectangles by top-left corner and size.
local function build(d)
  if d.kind ~= 'rect' or d.angle ~= 0 then return nil end
  return { x = d.x - d.w / 2, y = d.y - d.h / 2, w = d.w, h = d.h }
end

-- A two-item world per pair (one cell size above the largest item).
local function pair(a, b)
  local world = bump.newWorld(64)
  world:add(a, a.x, a.y, a.w, a.h)
  world:add(b, b.x, b.y, b.w, b.h)
  local ctx = { world = world, item = a, x = a.x, y = a.y, w = a.w, h = a.h }
  return ctx, ctx
end

A.methods = {
  {
    name = 'world:project',
    build = build,
    pair = pair,
    test = function(ctx)
      local x, y = ctx.x, ctx.y
      local cols, len = ctx.world:project(ctx.item, x, y, ctx.w, ctx.h, x, y)
      if len == 0 then return false, 0 end
      local c = cols[1]
      if not c.overlaps then return false, 0 end
      local dx, dy = c.touch.x - x, c.touch.y - y
      return true, math.sqrt(dx * dx + dy * dy)
    end,
  },
}

return A
