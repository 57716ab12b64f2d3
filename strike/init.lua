--- strike: 2D collision detection for LÖVE and any Lua (5.1, 5.2, 5.3, 5.4, LuaJIT).
--- Separating-axis tests between convex shapes, grouped into colliders.
---
--- Conventions (README.md, "Conventions"):
---  * coordinates are plain numbers; with LÖVE, y grows downward;
---  * polygons are stored in positive winding (positive shoelace area: counter-clockwise
---    with y up, clockwise on a LÖVE screen); edge normals point outward;
---  * an MTV from S.AT(a, b) or S.triking(a, b) points from a toward b: moving b by +mtv,
---    or a by -mtv, separates them;
---  * touching is not colliding: shapes that only share boundary points do not collide.
local ROOT = (...):gsub('%.init$', '')

local registry = require(ROOT .. '.registry')
local MTV = require(ROOT .. '.collide.MTV')
local pair = require(ROOT .. '.collide.kinds').pair
local compound = require(ROOT .. '.collide.compound')
local args = require(ROOT .. '.collide.args')
local Shape = require(ROOT .. '.base.Shape')
local Collider = require(ROOT .. '.colliders.Collider')
local check = require(ROOT .. '.check')
local reserved = require(ROOT .. '.reserved')
local layout = require(ROOT .. '.base.layout')
local COUNT, DIRTY = layout.COUNT, layout.DIRTY

local describe, what, fail = check.describe, check.what, check.fail
local root = Shape._rootOf

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
local SHAPES = { 'ConvexPolygon', 'Circle', 'Edge', 'Ellipse', 'Rectangle', 'RegularPolygon', 'Point', 'Capsule' }
for _, name in ipairs(SHAPES) do
  S.hapes[name] = require(ROOT .. '.shapes.' .. name)
  local _ = S.trikers[name]
end
for _, name in ipairs({ 'Capsule', 'Concave', 'Chain' }) do
  S.trikers[name] = require(ROOT .. '.colliders.' .. name)
end

-- Argument checks (strike/collide/args.lua): a shape is a table with a pose stamp and a
-- registered kind, a collider one with a leaf cache (see colliders/Collider.lua).
local isShape, isCollider = args.isShape, args.isCollider
local badShape, badBody, badOut = args.badShape, args.badBody, args.badOut

--- Separating-axis test between two convex shapes. Always returns an MTV (filled into
--- `out` when given); check `mtv.separating`. The vector points from shape1 toward shape2.
---@param shape1 strike.Shape
---@param shape2 strike.Shape
---@param out strike.MTV|nil
---@return strike.MTV
function S.AT(shape1, shape2, out)
  -- (the argument checks ride on the lookups of the kernel: a shape is a table with a pose
  -- stamp and a registered kind; `out` may be nil or a table that is not one of strike's
  -- objects other than an MTV)
  local row = type(shape1) == 'table' and shape1._pose ~= nil and pair[shape1._kind]
  local ops = row and type(shape2) == 'table' and shape2._pose ~= nil and row[shape2._kind]
  if not ops then
    if not row then badShape('strike.AT', 1, shape1) end
    if type(shape2) ~= 'table' or not isShape(shape2) then badShape('strike.AT', 2, shape2) end
    args.noKernel('strike.AT', shape1, shape2, shape1, shape2)
  end
  if out == nil then
    out = MTV()
  elseif type(out) ~= 'table' or (out._type ~= 'mtv' and out._type ~= nil) then
    badOut('strike.AT', out, 3)
  end
  ops.collide(shape1, shape2, out)
  out.collider = shape1._parent and root(shape1) or shape1
  out.collided = shape2._parent and root(shape2) or shape2
  out._poseA, out._poseB = shape1._pose, shape2._pose
  return out
end

--- Collision between two colliders (or shapes): the shortest push of collider2 that leaves
--- none of its leaf shapes overlapping any of collider1's (the outline rule: for one leaf
--- each, their MTV), or false when no pair collides. Members of one collider never collide
--- with each other (nor with the members of colliders nested in it). The vector points
--- from collider1 toward collider2 (docs/collision.md).
---@param collider1 strike.Collider|strike.Shape
---@param collider2 strike.Collider|strike.Shape
---@param out strike.MTV|nil filled and returned on a collision; its contents are unspecified after false
---@return strike.MTV|false
S.triking = compound.collide

local scratch = MTV() -- S.ite's re-test of shapes that moved
local scratchCompound = MTV() -- and of bodies with several members
-- (each lets go of the shapes and bodies it names once tested into: S.ite reads its numbers
-- only, and a body the game drops is not kept alive by strike)
local letGo = MTV._letGo
local one1, one2 = {}, {} -- (one-slot leaf lists for bare shapes)

-- A body's leaves: a collider's leaf list, or a bare shape in `one`.
local function leavesOf(body, one)
  if body._shapes then return Collider._leafList(body) end
  one[1] = body
  return one, 1
end

-- Move the points of a contact list past its count k to out._spares, where the next call's
-- points are taken from (collide/contact.lua, setPoint): #out is the count, whatever the
-- list held before, and its tables are reused. A spare point lets go of its shapes (a member
-- removed from a body is not kept alive by a list that once had a point of it).
local function trim(out, k)
  local n = #out
  if n > k then
    local spares = out._spares or {}
    out._spares = spares
    for i = n, k + 1, -1 do
      local p = out[i]
      p.colliderShape, p.collidedShape = false, false
      spares[#spares + 1], out[i] = p, nil
    end
  end
end

-- S.ite for bodies with several members (compound.contacts): re-tested when either of the
-- MTV's shapes moved since.
local function compoundContacts(mtv, a, b, c1, l1, n1, c2, l2, n2, out)
  local m = mtv
  if a._pose ~= mtv._poseA or b._pose ~= mtv._poseB then
    m = compound.collide(c1, c2, scratchCompound)
    letGo(scratchCompound)
    if not m then return nil end
  end
  if not (m.depth > 0) then return nil end -- luacheck: ignore 581 (NaN reads as no collision)
  out = out or {}
  local k = compound.contacts(m, l1, n1, l2, n2, out)
  trim(out, k)
  if k == 0 then return nil end
  out.count, out.nx, out.ny = k, m.nx, m.ny
  return out
end

-- The fields S.ite reads from an MTV it uses as it is (a setter or a hand edit may have
-- broken them): numbers, and an edgeIndex naming a face of its shapes (or 0).
local function checkFace(m, a, b)
  local e = m.edgeIndex
  if type(m.nx) ~= 'number' or type(m.ny) ~= 'number' or type(m.depth) ~= 'number' then
    fail('strike.ite: the MTV\'s nx, ny and depth must be numbers (an MTV from S.AT, S.triking or S.MTV)')
  end
  if type(e) ~= 'number' or e % 1 ~= 0 or (e > 0 and e > (a[COUNT] or 0)) or (e < 0 and -e > (b[COUNT] or 0)) then
    fail(('strike.ite: the MTV\'s edgeIndex must be 0, i for face i of colliderShape (it has %d) or -j for'
      .. ' face j of collidedShape (it has %d), got %s'):format(a[COUNT] or 0, b[COUNT] or 0, describe(e)))
  end
end

local function checkMTV(fname, mtv)
  if type(mtv) ~= 'table' or type(mtv.x) ~= 'number' or type(mtv.y) ~= 'number' then
    fail(('%s: argument 1 must be an MTV, got %s'):format(fname, what(mtv)))
  end
end

--- Contact points of a collision (docs/collision.md, "Contacts"): a list of points
--- `{x =, y =, depth =, id =, nx =, ny =, colliderShape =, collidedShape =}` (the shapes whose
--- features touch, and the point's unit normal from the first toward the second) with
--- `count` and `nx, ny` (the MTV's direction), or nil for a separating MTV. Between two
--- shapes: 1 or 2 points, midway between the two surfaces, with the MTV's normal. Between
--- bodies with several members: every member pair that touches once the second body has
--- moved by the MTV gives up to 2 points where it touches then (on both surfaces), with its
--- own face normal and depth along it. `id` names the features that touch and stays the
--- same while they do. The points describe
--- the shapes as they are when S.ite is called: when either shape has moved since the MTV
--- was computed, the pair is tested again (nil when it no longer collides; the MTV itself
--- is left as it is). With `out`, its tables are reused and nothing is allocated once it
--- has held as many points.
---@param mtv strike.MTV
---@param out table|nil
---@return table|nil contacts
function S.ite(mtv, out)
  checkMTV('strike.ite', mtv)
  if out ~= nil and (type(out) ~= 'table' or out._type ~= nil) then -- (not a shape, collider or MTV)
    fail(('strike.ite: argument 2 (out) must be a table for the contacts (a previous result, or {}), got %s')
      :format(what(out)))
  end
  if mtv.separating then return nil end
  local a, b = mtv.colliderShape, mtv.collidedShape
  if type(a) ~= 'table' or not isShape(a) or type(b) ~= 'table' or not isShape(b) then
    local field, v = 'colliderShape', a
    if type(a) == 'table' and isShape(a) then field, v = 'collidedShape', b end
    reserved.check('strike.ite', 'the MTV\'s ' .. field, v)
    fail(('strike.ite: the MTV must come from S.AT or S.triking (its %s is %s, not a strike shape)')
      :format(field, what(v)))
  end
  local ops = pair[a._kind][b._kind]
  if not ops then args.noKernel('strike.ite', a, b) end
  local c1, c2 = mtv.collider, mtv.collided
  if a._kind ~= 'chain' and b._kind ~= 'chain' and (c1 ~= a or c2 ~= b) and type(c1) == 'table'
    and type(c2) == 'table' and (isCollider(c1) or isShape(c1)) and (isCollider(c2) or isShape(c2)) then
    -- bodies with several members between them: the outline's contacts
    local l1, n1 = leavesOf(c1, one1)
    local l2, n2 = leavesOf(c2, one2)
    if n1 + n2 > 2 then
      local contacts = compoundContacts(mtv, a, b, c1, l1, n1, c2, l2, n2, out)
      one1[1], one2[1] = nil, nil -- (bare shapes are not kept alive by strike)
      return contacts
    end
  end
  local m = mtv
  if a._pose ~= mtv._poseA or b._pose ~= mtv._poseB then
    m = ops.collide(a, b, scratch)
    letGo(scratch)
  else
    checkFace(m, a, b)
  end
  if not (m.depth > 0) then return nil end -- luacheck: ignore 581 (NaN reads as no collision)
  if a[DIRTY] then a:_refresh() end
  if b[DIRTY] then b:_refresh() end
  out = out or {}
  local k = ops.contact(a, b, m.nx, m.ny, m.depth, m.edgeIndex, out)
  if k == 0 then return nil end
  if out[k + 1] ~= nil then trim(out, k) end
  -- (every point names its pair and its normal, as a compound's do: a reused `out` that held
  -- a compound's points must not keep naming that compound's members)
  for i = 1, k do
    local p = out[i]
    p.colliderShape, p.collidedShape, p.nx, p.ny = a, b, m.nx, m.ny
  end
  out.count, out.nx, out.ny = k, m.nx, m.ny
  return out
end

-- A body S.ettle or S.hove moves: the MTV's `collider` or `collided` field.
local function checkSide(fname, mtv, field)
  local v = mtv[field]
  if type(v) ~= 'table' or not (isCollider(v) or isShape(v)) then
    reserved.check(fname, 'the MTV\'s ' .. field, v)
    fail(('%s: the MTV\'s %s must be a strike collider or shape (as in an MTV from S.AT or S.triking), got %s')
      :format(fname, field, what(v)))
  end
end

-- What S.ettle (both sides) and S.hove (the collided side) read besides the sides: a
-- finite vector, so that the error names them rather than the translate they call.
local function checkMove(fname, mtv, both)
  if not (check.finite(mtv.x) and check.finite(mtv.y)) then
    fail(('%s: the MTV\'s x and y must be finite numbers, got %s and %s'):format(fname, describe(mtv.x),
      describe(mtv.y)))
  end
  if both then checkSide(fname, mtv, 'collider') end
  checkSide(fname, mtv, 'collided')
end

--- Resolve a collision by moving both sides half way: mtv.collider by -mtv / 2 and
--- mtv.collided by +mtv / 2. Does nothing for a separating MTV.
---@param mtv strike.MTV
function S.ettle(mtv)
  checkMTV('strike.ettle', mtv)
  if mtv.separating then return end
  checkMove('strike.ettle', mtv, true)
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
  checkMove('strike.hove', mtv, false)
  mtv.collided:translate(mtv.x, mtv.y)
end

local function checkBody(fname, v, i)
  if type(v) ~= 'table' or not (isCollider(v) or isShape(v)) then badBody(fname, i, v) end
end

-- A collider without leaves: its box and circle are placeholders at (0, 0), not a place.
local function empty(v) return v._single ~= nil and v:getShapeCount() == 0 end

--- Bounding-circle test (centroid and radius) for colliders or shapes: true when the
--- circles overlap (touching is not overlapping). An empty collider overlaps nothing.
---@param a strike.Collider|strike.Shape
---@param b strike.Collider|strike.Shape
---@return boolean
function S.ircle(a, b)
  checkBody('strike.ircle', a, 1)
  checkBody('strike.ircle', b, 2)
  if empty(a) or empty(b) then return false end
  local ax, ay = a:getCentroid()
  local bx, by = b:getCentroid()
  local r = a:getRadius() + b:getRadius()
  local dx, dy = bx - ax, by - ay
  return dx * dx + dy * dy < r * r
end

--- Bounding-box test for colliders or shapes: true when the boxes overlap (touching is
--- not overlapping). An empty collider overlaps nothing.
---@param a strike.Collider|strike.Shape
---@param b strike.Collider|strike.Shape
---@return boolean
function S.aabb(a, b)
  checkBody('strike.aabb', a, 1)
  checkBody('strike.aabb', b, 2)
  if empty(a) or empty(b) then return false end
  local ax0, ay0, ax1, ay1 = a:getBounds()
  local bx0, by0, bx1, by1 = b:getBounds()
  return ax0 < bx1 and bx0 < ax1 and ay0 < by1 and by0 < ay1
end

local sweep = require(ROOT .. '.motion.sweep')
local separation = require(ROOT .. '.motion.separation')

--- Sweep body a by (dx, dy), turning by `angle` (radians, default 0) about its centroid, against
--- body b, which stays (strike/motion/sweep.lua; docs/moving.md, "Sweeps"): false when they never
--- touch, else the hit `{t =, x =, y =, nx =, ny =, overlapping =}` (filled into `out` when
--- given): t in [0, 1] the fraction of the move at the first touch, (x, y) where they touch,
--- (nx, ny) the unit normal from b toward a; bodies that already overlap give t = 0 and
--- overlapping = true.
---@param a strike.Collider|strike.Shape
---@param dx number
---@param dy number
---@param b strike.Collider|strike.Shape
---@param angle number|nil
---@param out table|nil
---@return table|false
function S.weep(a, dx, dy, b, angle, out) return sweep.weep(a, dx, dy, b, angle, out) end

--- The distance between two bodies and the closest points on each: `d, ax, ay, bx, by`
--- (strike/motion/separation.lua; docs/collision.md, "Distance"); for overlapping bodies d is
--- minus the depth, and the points are those of each that reach deepest into the other.
---@param a strike.Collider|strike.Shape
---@param b strike.Collider|strike.Shape
---@return number d
---@return number ax
---@return number ay
---@return number bx
---@return number by
function S.eparation(a, b) return separation.eparation(a, b) end

local Space = require(ROOT .. '.space.Space')
require(ROOT .. '.space.motion') -- (Space:cast, Space:move, Space:addResponse)
Space._ite = S.ite

--- A new, empty space: a world of colliders and shapes with a broadphase, exact queries,
--- layers and contact events (strike/space/Space.lua; docs/space.md).
---@return strike.Space
function S.pace() return Space() end

--- Load a Tiled map (Tiled's Lua export, or a JSON map decoded into the same tables) into a
--- space: its collidable objects and tiles as bodies, a tile layer's full-square tiles merged
--- into one body per connected region (strike/tiled/; docs/tiled.md). Returns
--- the level: `bodies` (in map order), `byId[id]` (the body of the Tiled object with that
--- id), `objectOf[body]` (the Tiled object, or for tiles {layer =, tile =, ...}) and
--- `remove()`. Bad input is an error naming the layer and object, and adds nothing.
---@param map table
---@param space strike.Space
---@param opts table|nil {layers = {names}}: layers to load as collidable
---@return strike.Level
function S.tiled(map, space, opts) return require(ROOT .. '.tiled.level').load(map, space, opts) end

-- LÖVE debug drawing, in strike/draw.lua, the only file that reads `love`; it is loaded on
-- the first call, so strike works without LÖVE. Each restores the colour it found.
local function drawing() return require(ROOT .. '.draw') end

--- Draw a colliding MTV (red) from the first shape's centroid, and the line between the
--- two shapes' centroids. Nothing for a separating MTV.
---@param mtv strike.MTV
function S.howMTV(mtv) drawing().mtv(mtv) end

--- Draw the outward normals of a collider's (or shape's) shapes (cyan), `len` long
--- (default 15); circles get eight.
---@param collider strike.Collider|strike.Shape
---@param len number|nil
function S.howNorms(collider, len) drawing().normals(collider, len) end

--- Draw both shapes' projections on the MTV's axis (yellow), side by side.
---@param mtv strike.MTV
function S.howProj(mtv) drawing().projections(mtv) end

--- Draw the contact points from S.ite (green) with their normal, `len` long (default 15).
---@param contacts table|nil
---@param len number|nil
function S.howContacts(contacts, len) drawing().contacts(contacts, len) end

--- Cast a ray at a shape or collider and draw it (magenta) up to its first hit, with the
--- hit point and normal. Returns the hit's distance, or nil.
---@param body strike.Shape|strike.Collider
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param maxDistance number|nil
---@return number|nil
function S.howRay(body, x, y, dx, dy, maxDistance) return drawing().ray(body, x, y, dx, dy, maxDistance) end

--- Draw a space (S.pace): its bodies in the current colour and its broadphase's boxes.
---@param space strike.Space
function S.howSpace(space) drawing().space(space) end

return S
