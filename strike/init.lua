--- strike: 2D collision detection for LÖVE and any Lua (5.1, 5.2, 5.3, 5.4, LuaJIT).
--- Separating-axis tests between convex shapes, grouped into colliders.
---
--- Conventions (README, "Conventions"):
---  * coordinates are plain numbers; with LÖVE, y grows downward;
---  * polygons are stored in positive winding (positive shoelace area: counter-clockwise
---    with y up, clockwise on a LÖVE screen); edge normals point outward;
---  * an MTV from S.AT(a, b) or S.triking(a, b) points from a toward b: moving b by +mtv,
---    or a by -mtv, separates them;
---  * touching is not colliding: shapes that only share boundary points do not collide.
local ROOT = (...):gsub('%.init$', '')

local registry = require(ROOT .. '.registry')
local MTV = require(ROOT .. '.collide.MTV')
local dispatch = require(ROOT .. '.collide.dispatch')
local check = require(ROOT .. '.check')

local describe, fail = check.describe, check.fail
local min, max = math.min, math.max

---@class strike
local S = {
  _VERSION = 'strike 0.1.0',
  _DESCRIPTION = '2D collision detection for LÖVE and any Lua: convex shapes, colliders, SAT',
  _LICENSE = 'MIT',
}

S.hapes, S.trikers = registry.new()
--- The MTV class, so a game can make its own `out` objects: S.MTV(dx, dy, ...).
S.MTV = MTV

-- Built-in classes, registered eagerly so that pairs(S.hapes) lists them.
for _, name in ipairs({ 'ConvexPolygon', 'Circle', 'Edge', 'Ellipse', 'Rectangle', 'RegularPolygon', 'Point' }) do
  S.hapes[name] = require(ROOT .. '.shapes.' .. name)
  local _ = S.trikers[name]
end
for _, name in ipairs({ 'Capsule', 'Concave', 'Chain' }) do
  S.trikers[name] = require(ROOT .. '.colliders.' .. name)
end

local function badShape(fname, i, v)
  if type(v) == 'table' and v.type == 'collider' then
    fail(('%s: argument %d must be a shape, got a collider (use S.triking for colliders)'):format(fname, i))
  end
  fail(('%s: argument %d must be a strike shape, got %s'):format(fname, i, describe(v)))
end

local function checkOut(fname, out, i)
  if out ~= nil and type(out) ~= 'table' then
    fail(('%s: argument %d (out) must be a table such as S.MTV(), got %s'):format(fname, i, describe(out)))
  end
end

local root = require(ROOT .. '.collide.sat').root

--- Separating-axis test between two convex shapes. Always returns an MTV (filled into
--- `out` when given); check `mtv.separating`. The vector points from shape1 toward shape2.
---@param shape1 strike.Shape @param shape2 strike.Shape @param out strike.MTV|nil
---@return strike.MTV
function S.AT(shape1, shape2, out)
  local row = type(shape1) == 'table' and dispatch[shape1.kind]
  local test = row and type(shape2) == 'table' and row[shape2.kind]
  if not test then
    if not row then badShape('strike.AT', 1, shape1) end
    badShape('strike.AT', 2, shape2)
  end
  if out == nil then out = MTV() elseif type(out) ~= 'table' then checkOut('strike.AT', out, 3) end
  test(shape1, shape2, out)
  out.collider, out.collided = root(shape1), root(shape2)
  return out
end

-- Scratch state for S.triking: two MTVs swapped as the best one changes, and one-slot
-- leaf lists for bare shapes.
local tmpA, tmpB = MTV(), MTV()
local single1, single2 = {}, {}

local function leavesOf(v, slot, fname, i)
  if type(v) == 'table' then
    if v.type == 'collider' then
      if not v._leavesOK then v._refreshLeaves(v) end
      return v._leaves, v._nleaves
    elseif dispatch[v.kind] then
      slot[1] = v
      return slot, 1
    end
  end
  fail(('%s: argument %d must be a strike collider or shape, got %s'):format(fname, i, describe(v)))
end

--- Collision between two colliders (or shapes): the deepest MTV over all pairs of their
--- leaf shapes, or false when no pair collides. Members of one collider never collide
--- with each other (nor with the members of colliders nested in it). The vector points
--- from collider1 toward collider2.
---@param collider1 strike.Collider|strike.Shape @param collider2 strike.Collider|strike.Shape
---@param out strike.MTV|nil filled and returned on a collision; its contents are unspecified after false
---@return strike.MTV|false
function S.triking(collider1, collider2, out)
  -- One leaf each, the common case: straight-line code (LuaJIT traces one-trip loops
  -- badly), tested into the caller's `out` when there is one. `_single` is a collider's
  -- only leaf while its leaf list is current; a bare shape is its own.
  local s1 = type(collider1) == 'table' and collider1._single
  if s1 == nil and dispatch[collider1.kind] then s1 = collider1 end
  local s2 = false
  if s1 then
    s2 = type(collider2) == 'table' and collider2._single
    if s2 == nil and dispatch[collider2.kind] then s2 = collider2 end
  end
  local l1, n1, l2, n2
  if not s2 then
    l1, n1 = leavesOf(collider1, single1, 'strike.triking', 1)
    l2, n2 = leavesOf(collider2, single2, 'strike.triking', 2)
  end
  if out ~= nil and type(out) ~= 'table' then checkOut('strike.triking', out, 3) end
  local r1, r2 = collider1, collider2
  while r1.parent do r1 = r1.parent end
  while r2.parent do r2 = r2.parent end
  if r1 == r2 then -- every leaf pair would share a root
    single1[1], single2[1] = nil, nil
    return false
  end
  if s2 then
    if s1._dirty then s1:_refresh() end
    if s2._dirty then s2:_refresh() end
    -- (a shape's bounds are its entries 1 to 4: minx, miny, maxx, maxy)
    if s1[3] < s2[1] or s2[3] < s1[1] or s1[4] < s2[2] or s2[4] < s1[2] then
      return false -- the bounds do not even meet
    end
    local m = dispatch[s1.kind][s2.kind](s1, s2, out or tmpA)
    if not (m.depth > 0) then return false end -- luacheck: ignore 581 (NaN reads as no collision)
    if not out then out = MTV.set(MTV(), m) end
    out.collider, out.collided = r1, r2
    return out
  end
  -- Test into `tmp`; a deeper result becomes `best` and the other buffer becomes `tmp`.
  -- With an `out` table it is one of the two buffers, so the usual single hit needs no copy.
  local best, tmp, found = tmpA, out or tmpB, false
  local bestDepth = 0
  for i = 1, n1 do
    local a = l1[i]
    if a._dirty then a:_refresh() end
    local ax0, ay0, ax1, ay1 = a[1], a[2], a[3], a[4] -- (its bounds)
    local row = dispatch[a.kind]
    for j = 1, n2 do
      local b = l2[j]
      if b._dirty then b:_refresh() end
      -- Bounds meet (closed intervals: an axis-aligned edge or a point has a flat box;
      -- the narrow phase decides touching), as two tests instead of four: fewer trace
      -- exits under LuaJIT.
      if min(ax1, b[3]) >= max(ax0, b[1]) and min(ay1, b[4]) >= max(ay0, b[2]) then
        row[b.kind](a, b, tmp)
        local d = tmp.depth
        if d > bestDepth then -- (false for NaN and for separating results)
          best, tmp, found, bestDepth = tmp, best, true, d
        end
      end
    end
  end
  single1[1], single2[1] = nil, nil -- (bare shapes are not kept alive by strike)
  if not found then return false end
  if best ~= out then out = MTV.set(out or MTV(), best) end
  out.collider, out.collided = r1, r2
  return out
end

local contact = require(ROOT .. '.collide.contact')

local function checkMTV(fname, mtv)
  if type(mtv) ~= 'table' or type(mtv.x) ~= 'number' or type(mtv.y) ~= 'number' then
    fail(('%s: argument 1 must be an MTV, got %s'):format(fname, describe(mtv)))
  end
end

--- Contact points of a collision (see "Contacts" in the README): a list of 1 or 2 points
--- `{x =, y =, depth =, id =}` with `count` and the normal `nx, ny` (the MTV's direction),
--- or nil for a separating MTV. Each point lies midway between the two surfaces; `id`
--- names the features that touch and stays the same while they do. With `out`, its
--- tables are reused and nothing is allocated once it has held two points.
---@param mtv strike.MTV @param out table|nil
---@return table|nil contacts
function S.ite(mtv, out)
  checkMTV('strike.ite', mtv)
  if out ~= nil and type(out) ~= 'table' then checkOut('strike.ite', out, 2) end
  if mtv.separating then return nil end
  local a, b = mtv.colliderShape, mtv.collidedShape
  if type(a) ~= 'table' or not dispatch[a.kind] or type(b) ~= 'table' or not dispatch[b.kind] then
    fail('strike.ite: the MTV must come from S.AT or S.triking (its colliderShape and collidedShape are not shapes)')
  end
  out = out or {}
  local k = contact.manifold(mtv, out)
  if k == 0 then return nil end
  if k == 1 and out[2] then out._spare, out[2] = out[2], nil end
  out.count, out.nx, out.ny = k, mtv.nx, mtv.ny
  return out
end

--- Resolve a collision by moving both sides half way: mtv.collider by -mtv / 2 and
--- mtv.collided by +mtv / 2. Does nothing for a separating MTV.
---@param mtv strike.MTV
function S.ettle(mtv)
  checkMTV('strike.ettle', mtv)
  if mtv.separating then return end
  local hx, hy = mtv.x / 2, mtv.y / 2
  mtv.collider:translate(-hx, -hy)
  mtv.collided:translate(hx, hy)
end

--- Resolve a collision by moving only mtv.collided, by the full +mtv (the collider side
--- stays put: good against static geometry). Does nothing for a separating MTV.
---@param mtv strike.MTV
function S.hove(mtv)
  checkMTV('strike.hove', mtv)
  if mtv.separating then return end
  mtv.collided:translate(mtv.x, mtv.y)
end

local function checkBody(fname, v, i)
  if type(v) ~= 'table' or (v.type ~= 'collider' and not dispatch[v.kind]) then
    fail(('%s: argument %d must be a strike collider or shape, got %s'):format(fname, i, describe(v)))
  end
end

--- Bounding-circle test (centroid and radius) for colliders or shapes: true when the
--- circles overlap (touching is not overlapping).
---@param a strike.Collider|strike.Shape @param b strike.Collider|strike.Shape
---@return boolean
function S.ircle(a, b)
  checkBody('strike.ircle', a, 1)
  checkBody('strike.ircle', b, 2)
  local ax, ay = a:getCentroid()
  local bx, by = b:getCentroid()
  local r = a:getRadius() + b:getRadius()
  local dx, dy = bx - ax, by - ay
  return dx * dx + dy * dy < r * r
end

--- Bounding-box test for colliders or shapes: true when the boxes overlap (touching is
--- not overlapping).
---@param a strike.Collider|strike.Shape @param b strike.Collider|strike.Shape
---@return boolean
function S.aabb(a, b)
  checkBody('strike.aabb', a, 1)
  checkBody('strike.aabb', b, 2)
  local ax0, ay0, ax1, ay1 = a:getBounds()
  local bx0, by0, bx1, by1 = b:getBounds()
  return ax0 < bx1 and bx0 < ax1 and ay0 < by1 and by0 < ay1
end

-- LÖVE debug drawing, in strike/draw.lua, the only file that reads `love`; it is loaded on
-- the first call, so strike works without LÖVE. Each restores the colour it found.
local function drawing() return require(ROOT .. '.draw') end

--- Draw a colliding MTV (red) from the first shape's centroid, and the line between the
--- two shapes' centroids. Nothing for a separating MTV.
---@param mtv strike.MTV
function S.howMTV(mtv) drawing().mtv(mtv) end

--- Draw the outward normals of a collider's (or shape's) shapes (cyan), `len` long
--- (default 15); circles get eight.
---@param collider strike.Collider|strike.Shape @param len number|nil
function S.howNorms(collider, len) drawing().normals(collider, len) end

--- Draw both shapes' projections on the MTV's axis (yellow), side by side.
---@param mtv strike.MTV
function S.howProj(mtv) drawing().projections(mtv) end

--- Draw the contact points from S.ite (green) with their normal, `len` long (default 15).
---@param contacts table|nil @param len number|nil
function S.howContacts(contacts, len) drawing().contacts(contacts, len) end

--- Cast a ray at a shape or collider and draw it (magenta) up to its first hit, with the
--- hit point and normal. Returns the hit's distance, or nil.
---@param body strike.Shape|strike.Collider @param x number @param y number @param dx number @param dy number
---@param maxDistance number|nil
---@return number|nil
function S.howRay(body, x, y, dx, dy, maxDistance) return drawing().ray(body, x, y, dx, dy, maxDistance) end

return S
