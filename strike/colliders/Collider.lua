--- A Collider is a tree of shapes and colliders that move together. Its members never
--- collide with each other. Area, centroid, radius and bounds are aggregates of the leaf
--- shapes, cached and recomputed on the next query after anything in the tree changes.
--- Leaves that are pieces of a compound (S.trikers.Concave's) may mark faces as seams, cuts
--- inside it (`_seams`, strike/base/VertexShape.lua): containsPoint and the ray queries
--- treat those as inside, at any depth of nesting.
---
--- The cache protocol (shapes and colliders). Every cached value has one flag; whoever
--- changes what it depends on clears the flag, and the next reader refreshes it.
---
---   flag (owner)          guards                        cleared by                   refreshed by
---   slot DIRTY (shape)    its world data (layout.lua:   Shape:_touch: every          the kind's _refresh, called by
---                         bounds, radius, vertex        transform of the shape,      every reader first (getters,
---                         records)                      and Shape:_place, a          narrow phase, rays, contacts,
---                                                       collider moving it           collide/compound.lua)
---   `_pose` (shape)       a stamp, not a flag: a new    the same                     (read by S.ite against the
---                         number on every move                                       MTV's `_poseA`, `_poseB`)
---   `_nleaves` >= 0       the flat leaf list `_leaves`, invalidate(): add, remove,   refreshLeaves (via _leafList,
---     (collider; -1       its length `_nleaves`,        consolidate, on the          elems, getShapeCount, the
---     when stale)         `_leafPos` (made by the first collider changed and every   transforms, rays, project,
---                         elems) and `_single` (the     one holding it               containsPoint, radius), for
---                         only leaf or false;                                        the collider asked only
---                         S.triking's fast path)
---   `_massOK`             area and centroid (slots:     invalidate(), and            refreshMass (getArea,
---     (collider)          layout.lua), and the slot     Shape:_touch of any leaf     getCentroid, getAreaCentroid)
---                         CCOUNT, its number of leaves  below it
---   `_clean` (collider)   bounds and radius (slots),    the same as `_massOK`        refresh (getBbox, getBounds,
---                         and CCOUNT too                                             getRadius, calcAreaCentroid)
---
--- A reader that needs a dirty shape's bounds alone (a collider's `refresh`, S.pace) may take
--- them without its vertex records when it was never refreshed (VertexShape._boundsOnly): the
--- shape stays dirty, and its first other reader refreshes it, to the same bounds.
---
--- Invariant: when a collider's `_massOK` or `_clean` is false, so is that flag on every
--- enclosing collider. Clearing keeps it by walking up from the change to the root, and a
--- move (Shape:_touch) may stop at the first collider whose flags are already false
--- (everything above it is false too). Refreshing keeps it by working bottom-up: a collider
--- refreshes its stale nested colliders first, and refreshing an inner collider alone
--- leaves the outer ones stale, which is allowed. A leaf list is made for the collider that
--- is asked for it, from a walk over everything it holds: the lists of the colliders nested
--- in it are left as they are (stale until they are asked), so that a chain of colliders
--- nested n deep costs O(n), not one list per level; a change of members (invalidate)
--- therefore clears the lists all the way up to the root.
--- Transforms of a collider need only the leaf list, so moving a collider every frame
--- costs one world-data refresh per leaf, at the next query. spec/cache_spec.lua checks
--- every query on an outer collider after every change to a leaf of an inner one.
---
--- Depth. No walk over the tree recurses deeper than a few levels, so colliders nest to
--- any depth on every VM (spec/nesting_spec.lua: 20,000): refreshLeaves, copy, consolidate
--- and the diagnosis of a changed field are loops with an explicit stack; refreshMass,
--- refresh, shift and addAngle call themselves for the first SHALLOW levels below the
--- collider asked (the fastest way for the colliders games build, a level or two deep) and
--- hand the rest to such a loop; invalidate, Shape:_touch and getRoot walk up in a loop. The
--- loops share one stack, `walk`, from its slot `top` up, so that a walk that calls out (a
--- leaf's getAreaCentroid, a shape's copy) and meets another walk stays correct. A walk
--- allocates nothing once the stack has grown to the deepest tree walked.
local ROOT = (...):match('^(.-)%.colliders%.[^%.]+$')
local Object = require(ROOT .. '.class')
local Shape = require(ROOT .. '.base.Shape')
local boundsOnly = require(ROOT .. '.base.VertexShape')._boundsOnly
local check = require(ROOT .. '.check')
local compat = require(ROOT .. '.compat')
local unpack, tnew = compat.unpack, compat.tableNew
local rotate = require(ROOT .. '.vec').rotate
local checkPose = Shape._checkPose
local spaces, badLink = Shape._spaces, Shape._badLink
local layout = require(ROOT .. '.base.layout')
local RADIUS, SCALE = layout.RADIUS, layout.SCALE
local args = require(ROOT .. '.collide.args')

local cos, sin, huge, abs = math.cos, math.sin, math.huge, math.abs
local number, positive, optPoint, fail, describe = check.number, check.positive, check.optPoint, check.fail,
  check.describe
local badSelf, badCollider, type = check.badSelf, check.badCollider, type
local X, Y = layout.X, layout.Y
local MINX, MINY, MAXX, MAXY = layout.MINX, layout.MINY, layout.MAXX, layout.MAXY
local CRADIUS, CAREA, CAX, CAY = layout.CRADIUS, layout.CAREA, layout.CAX, layout.CAY
local CLEN, CLX, CLY, CSX, CSY = layout.CLEN, layout.CLX, layout.CLY, layout.CSX, layout.CSY
local DIRTY = layout.DIRTY
local CANGLE, CCOUNT, CSIZE = layout.CANGLE, layout.CCOUNT, layout.CSIZE

-- The walks' shared stack (see "Depth" above): a walk uses the slots above `top` and puts
-- `top` back when it is done, clearing what it put there.
local walk, top = {}, 0

---@class strike.Collider : strike.Object
---@field type string always 'collider'
---@field name string the class name, as S.trikers names it
local Collider = Object:extend()
Collider.type = 'collider'
Collider.name = 'Collider'
--- The class marker strike reads (see Shape._type). A collider's own fields are `_shapes`, its
--- children (unpack), `_parent` (getParent) and its caches below; every other name that does
--- not start with `_` is the game's.
Collider._type = 'collider'

local function isShape(v) return type(v) == 'table' and getmetatable(v) ~= nil and Object.is(v, Shape) end
local function isCollider(v) return type(v) == 'table' and getmetatable(v) ~= nil and Object.is(v, Collider) end

-- The failure path of a collider's list of children that is not its own (`_shapes`, whose
-- slot 0 names the collider), or of a member whose `_parent` does not hold it: a game's value
-- in a field of strike's is an error naming the field (strike/reserved.lua).
local function badShapes(self, fname)
  -- (the error ends the walks under way, which it unwinds: they let go of what they held)
  for k = #walk, 1, -1 do walk[k] = nil end
  top = 0
  local reserved = require(ROOT .. '.reserved')
  reserved.check(fname, 'the ' .. (reserved.classType(self) or 'collider'), self)
  fail(('%s: the collider\'s fields starting with _ are not as strike left them; %s'):format(fname, reserved.RULE))
end

-- The list of the children of `self` (the collider of a method that checked it), checked.
local function childrenOf(self, fname)
  local shapes = self._shapes
  if type(shapes) ~= 'table' or shapes[0] ~= self then badShapes(self, fname) end
  return shapes
end

-- The cache slots and flags, all stale (see the cache protocol above), laid out once, at
-- construction, so that the object's fields never move.
local function startCaches(self)
  if self[1] == nil then -- (made by LuaJIT's table.new, whose slots are nil, or not by _alloc)
    for k = 1, CSIZE do self[k] = 0 end
  end
  self._nleaves, self._massOK, self._clean, self._single = -1, false, false, false
end

--- A collider holding the given shapes and colliders (any number, nested to any depth).
---@param ... strike.Shape|strike.Collider
function Collider:new(...)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Collider:new') end
  self._shapes = { [0] = self } -- (slot 0: the list's owner, see childrenOf)
  startCaches(self)
  self:add(...)
end

--- (internal) Make `self`, a new collider, the collider of `shape`, which a single-shape
--- collider's constructor (colliders/single.lua) has just built as an instance of `cls`, a
--- registered shape class (so a strike shape): what Collider.new(self, shape) does, without
--- the checks of `add`, which a shape built a moment ago passes. A shape that would fail one
--- (not an instance of `cls`, its constructor never set its pose, or put it in a collider or
--- a space), or a collider class with an `add` of its own, takes Collider.new, its checks and
--- its errors.
---@param shape strike.Shape
---@param cls table
function Collider._newSingle(self, shape, cls)
  if type(shape) ~= 'table' or getmetatable(shape) ~= cls or rawget(shape, '_pose') == nil
    or rawget(shape, '_parent') ~= nil or rawget(shape, '_space') ~= nil or rawget(shape, '_sid') ~= nil
    or self.add ~= Collider.add then
    return Collider.new(self, shape)
  end
  self._shapes = { [0] = self, shape } -- (slot 0: the list's owner, see childrenOf)
  startCaches(self)
  shape._parent = self
end

--- The empty instance `Class(...)` fills (class.lua): a table with room for the slots and
--- for the fields a collider in a space has (as Shape._slots makes a shape: on the VMs other
--- than LuaJIT the constructor's nil fields size its hash part, and name the fields Lua 5.1
--- keeps there; a table that grew would have its slots rounded up to 32).
---@return table
function Collider._alloc()
  if tnew then return tnew(CSIZE, 8) end
  return { _shapes = nil, _nleaves = nil, _massOK = nil, _clean = nil, _single = nil, _leaves = nil, _space = nil,
    _sid = nil, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 }
end

--- (internal) For strike's own constructors: make `self`, a new instance of Collider or of
--- a subclass whose constructor has not run Collider.new, hold the shapes and colliders of
--- `parts` (a list, which becomes its list of children): what Collider.new(self, parts[1],
--- parts[2], ...) makes, without Collider:add's checks, which such members pass by
--- construction (each new, built by strike, in no collider and no space, and given once).
--- Returns self.
---@param self strike.Collider
---@param parts table
---@return strike.Collider
function Collider._take(self, parts)
  parts[0] = self -- (slot 0: the list's owner, see childrenOf)
  self._shapes = parts
  startCaches(self)
  for i = 1, #parts do parts[i]._parent = self end
  return self
end

--- (internal) A new Collider holding the shapes and colliders of `parts`, as Collider._take
--- makes it: what Collider(parts[1], parts[2], ...) makes, without the checks.
---@param parts table
---@return strike.Collider
function Collider._of(parts)
  return Collider._take(setmetatable(Collider._alloc(), Collider), parts)
end

-- The structure changed: clear every flag here and on every enclosing collider, up to the
-- root (the leaf lists of the colliders between may be stale already: see the cache
-- protocol), and, when the walk reaches a root in a space, queue it there, as Shape:_touch
-- does.
local function invalidate(self)
  local p = self
  while p do
    if p._clean == nil then badLink(self) end -- (a `_parent` a game set: see Shape:_touch)
    p._nleaves, p._massOK, p._clean, p._single = -1, false, false, false
    local up = p._parent
    if not up then
      local space = p._space
      if space then
        local moved = spaces[space]
        if not moved then badLink(self) end
        moved(space, p)
      end
    end
    p = up
  end
end

--- Add shapes and colliders as children. A child may belong to one collider only.
---@param ... strike.Shape|strike.Collider
---@return self
function Collider:add(...)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:add') end
  local shapes = self._shapes
  if not shapes then shapes = { [0] = self }; self._shapes = shapes end
  if type(shapes) ~= 'table' or shapes[0] ~= self then badShapes(self, 'strike.Collider:add') end
  if self._single == nil then
    -- (a collider whose constructor adds without calling Collider.new, as the original
    -- Strike's walkthrough does: its caches start here)
    startCaches(self)
  end
  for i = 1, select('#', ...) do
    local child = select(i, ...)
    if not (isShape(child) or isCollider(child)) then
      fail(('strike.Collider:add: argument %d must be a strike shape or collider, got %s'):format(i, describe(child)))
    end
    -- (an instance whose constructor never ran: args names what its class lacks, if
    -- anything, or says it was not built; a built shape's class was checked when it was)
    if isShape(child) then
      if child._pose == nil then args.badShape('strike.Collider:add', i, child) end
    elseif child._single == nil then
      args.badBody('strike.Collider:add', i, child)
    end
    if child._parent or rawget(child, '_space') or rawget(child, '_sid') ~= nil then
      -- (a `_parent`, `_space` or `_sid` the game set is an error naming it)
      require(ROOT .. '.reserved').check('strike.Collider:add', 'argument ' .. i, child)
    end
    if child._parent then
      fail(('strike.Collider:add: argument %d already belongs to a collider; remove it first or add a copy'):format(i))
    end
    if rawget(child, '_space') then
      fail(('strike.Collider:add: argument %d is in a space; remove it from the space first'):format(i))
    end
    for j = 1, i - 1 do
      if select(j, ...) == child then
        fail(('strike.Collider:add: argument %d is argument %d again; a body can be added once'):format(i, j))
      end
    end
    local p = self
    while p do
      if p == child then fail(('strike.Collider:add: argument %d would contain itself'):format(i)) end
      p = p._parent
      if p and p._clean == nil then badShapes(self, 'strike.Collider:add') end -- (a `_parent` a game set)
    end
  end
  for i = 1, select('#', ...) do
    local child = select(i, ...)
    child._parent = self
    shapes[#shapes + 1] = child
  end
  invalidate(self)
  return self
end

--- Remove the children at the given indices (numbered as before the call) and return them,
--- in the order asked. Each removed child is free to be added elsewhere.
---@param index integer
---@param ... integer
---@return strike.Shape|strike.Collider ...
function Collider:remove(index, ...)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:remove') end
  local shapes = childrenOf(self, 'strike.Collider:remove')
  local n = #shapes
  local idx = { index, ... }
  local count = select('#', ...) + 1
  local seen = {}
  for i = 1, count do
    local k = idx[i]
    check.integer(k, 'strike.Collider:remove', 'index', 1, n)
    if seen[k] then fail(('strike.Collider:remove: index %d given twice'):format(k)) end
    seen[k] = true
  end
  local removed = {}
  for i = 1, count do removed[i] = shapes[idx[i]] end
  local j = 0
  for i = 1, n do
    local c = shapes[i]
    shapes[i] = nil
    if seen[i] then
      c._parent = nil
    else
      j = j + 1
      shapes[j] = c
    end
  end
  invalidate(self)
  return unpack(removed, 1, count)
end

--- The direct children (shapes and colliders), not copies.
---@return strike.Shape|strike.Collider ...
function Collider:unpack()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:unpack') end
  local shapes = childrenOf(self, 'strike.Collider:unpack')
  return unpack(shapes, 1, #shapes)
end

-- Level 1: the flat list of leaves (`_leaves`, `_leafPos`, `_nleaves`, `_single`) of this
-- collider: a walk over everything it holds, depth first in order, with a stack of the lists
-- it is inside and the index to go on from in each. Nested colliders' own lists are left as
-- they are (see the cache protocol).
local function refreshLeaves(self)
  local shapes = childrenOf(self, 'strike')
  local leaves, pos = self._leaves, self._leafPos
  if pos then for k in pairs(pos) do pos[k] = nil end end -- (pos: made by elems, when first used)
  local nested = false
  for i = 1, #shapes do
    if shapes[i]._shapes then nested = true break end
  end
  if not nested then -- (the children are the leaves: the list is `shapes` itself, no copy)
    local nl = #shapes
    if pos then for i = 1, nl do pos[shapes[i]] = i end end
    self._leaves, self._nleaves, self._single = shapes, nl, nl == 1 and shapes[1]
    return
  end
  if not leaves or leaves == shapes then leaves = {}; self._leaves = leaves end
  local base = top
  local n, nl, list, i = base, 0, shapes, 1
  while true do
    local c = list[i]
    if c ~= nil then
      i = i + 1
      if c._shapes then -- (a collider: into its list, back here after it)
        walk[n + 1], walk[n + 2] = list, i
        n = n + 2
        top = n
        list, i = childrenOf(c, 'strike'), 1
      else
        nl = nl + 1
        leaves[nl] = c
        if pos then pos[c] = nl end
      end
    elseif n > base then -- (that list is done: back to the one holding it)
      list, i = walk[n - 1], walk[n]
      walk[n - 1], walk[n] = nil, nil
      n = n - 2
    else
      break
    end
  end
  top = base
  for k = #leaves, nl + 1, -1 do leaves[k] = nil end
  self._nleaves = nl
  self._single = nl == 1 and leaves[1]
end

--- The flat list of leaf shapes, depth first in insertion order, and its length (the
--- list is strike's: read it, never change it).
---@return strike.Shape[] leaves
---@return integer n
function Collider:_leafList()
  if self._nleaves < 0 then refreshLeaves(self) end
  return self._leaves, self._nleaves
end

-- The stale colliders nested in `self` (`flag`: '_massOK' or '_clean' false), each before the
-- ones it holds: breadth first into the shared stack, from slot base + 1 (self is there
-- first). Returns the last slot used. Their refresher then runs from the last back to the
-- first, so that each collider is refreshed after every stale one it holds (and every fresh
-- one holds only fresh ones: the invariant).
local function staleBelow(self, flag, base)
  local n = base + 1
  walk[n] = self
  local k = n
  while k <= n do
    local shapes = childrenOf(walk[k], 'strike')
    for i = 1, #shapes do
      local c = shapes[i]
      if c._shapes and not c[flag] then
        n = n + 1
        walk[n] = c
      end
    end
    k = k + 1
    top = n
  end
  return n
end

-- The levels of nesting that refreshMass, refresh, shift and addAngle go down by calling
-- themselves, the way shallow colliders are fastest; below that, a walk with the shared stack
-- takes over (see "Depth" above), so that neither Lua's stack nor C's grows with the depth.
local SHALLOW = 8

local massWalk

-- Level 2: area and centroid, and the leaf count, of a collider from its children's own
-- sums, refreshing first the stale colliders it holds (`depth` levels down already: nil at
-- the top). Needs no world vertices. Edges (no area) weigh by length, used when the whole
-- tree has no area.
local function refreshMass(self, depth)
  local shapes = self._shapes
  if type(shapes) ~= 'table' or shapes[0] ~= self then badShapes(self, 'strike') end
  local area, ax, ay, len, lx, ly, cnt, sx, sy = 0, 0, 0, 0, 0, 0, 0, 0, 0
  for i = 1, #shapes do
    local c = shapes[i]
    if c._shapes then
      if not c._massOK then
        depth = depth or 0
        if depth >= SHALLOW then return massWalk(self) end
        refreshMass(c, depth + 1)
      end
      area, ax, ay = area + c[CAREA], ax + c[CAX], ay + c[CAY]
      len, lx, ly = len + c[CLEN], lx + c[CLX], ly + c[CLY]
      cnt, sx, sy = cnt + c[CCOUNT], sx + c[CSX], sy + c[CSY]
    else
      local a, x, y = c:getAreaCentroid()
      if a > 0 then
        area, ax, ay = area + a, ax + a * x, ay + a * y
      else
        local l = 2 * c:getRadius()
        len, lx, ly = len + l, lx + l * x, ly + l * y
      end
      cnt, sx, sy = cnt + 1, sx + x, sy + y
    end
  end
  self[CAREA], self[CAX], self[CAY], self[CLEN], self[CLX], self[CLY] = area, ax, ay, len, lx, ly
  self[CSX], self[CSY], self[CCOUNT] = sx, sy, cnt
  if area > 0 then
    self[X], self[Y] = ax / area, ay / area
  elseif len > 0 then
    self[X], self[Y] = lx / len, ly / len
  elseif cnt > 0 then
    self[X], self[Y] = sx / cnt, sy / cnt
  else
    self[X], self[Y] = 0, 0
  end
  self._massOK = true
end

-- refreshMass of every stale collider in `self`, deepest first, `self` last: each then holds
-- fresh ones only (refreshMass, which came here, left `self` as it was).
function massWalk(self)
  local base = top
  local n = staleBelow(self, '_massOK', base)
  for k = n, base + 1, -1 do
    refreshMass(walk[k])
    walk[k] = nil
  end
  top = base
end

local boundsWalk

-- Level 3: bounds, and the leaf count, of a collider, refreshing first the stale colliders it
-- holds (as refreshMass). These need the leaves' world vertices.
-- (the bounds need no centroid: a body a space adds, or a bullet that only translates, never
-- computes one until something asks)
local function refresh(self, depth)
  local shapes = self._shapes
  if type(shapes) ~= 'table' or shapes[0] ~= self then badShapes(self, 'strike') end
  local minx, miny, maxx, maxy = huge, huge, -huge, -huge
  local cnt = 0
  for i = 1, #shapes do
    local c = shapes[i]
    local k = 1
    if c._shapes then
      if not c._clean then
        depth = depth or 0
        if depth >= SHALLOW then return boundsWalk(self) end
        refresh(c, depth + 1)
      end
      k = c[CCOUNT] -- (an empty nested collider bounds nothing)
    elseif c[DIRTY] then
      boundsOnly(c) -- (the bounds alone, for a leaf never refreshed: its vertices wait)
    end
    if k > 0 then
      local x0, y0, x1, y1 = c[MINX], c[MINY], c[MAXX], c[MAXY]
      if x0 < minx then minx = x0 end
      if y0 < miny then miny = y0 end
      if x1 > maxx then maxx = x1 end
      if y1 > maxy then maxy = y1 end
      cnt = cnt + k
    end
  end
  if cnt == 0 then minx, miny, maxx, maxy = 0, 0, 0, 0 end
  self[CRADIUS] = -1 -- (computed by the first getRadius: a space needs the bounds alone)
  self[MINX], self[MINY], self[MAXX], self[MAXY] = minx, miny, maxx, maxy
  self[CCOUNT] = cnt
  self._clean = true
end

-- refresh of every stale collider in `self`, deepest first, `self` last (as massWalk).
function boundsWalk(self)
  local base = top
  local n = staleBelow(self, '_clean', base)
  for k = n, base + 1, -1 do
    refresh(walk[k])
    walk[k] = nil
  end
  top = base
end
-- The radius about the centroid, of a clean collider (see getRadius).
local function radius(self)
  if not self._massOK then refreshMass(self) end
  if self._nleaves < 0 then refreshLeaves(self) end
  local cx, cy, leaves, r = self[X], self[Y], self._leaves, 0
  for i = 1, self._nleaves do
    local d = leaves[i]:_farthest(cx, cy)
    if d > r then r = d end
  end
  self[CRADIUS] = r
  return r
end

--- Recompute area and centroid now (they are also kept up to date automatically).
---@return self
function Collider:calcAreaCentroid()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:calcAreaCentroid') end
  self._massOK, self._clean = false, false
  refreshMass(self)
  refresh(self)
  return self
end

--- Recompute the radius now (it is also kept up to date automatically).
---@return self
function Collider:calcRadius()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:calcRadius') end
  return self:calcAreaCentroid()
end

--- Total area of the leaf shapes (overlapping members count twice; edges add nothing).
---@return number
function Collider:getArea()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:getArea') end
  if not self._massOK then refreshMass(self) end
  return self[CAREA]
end

--- Centroid: the area-weighted mean of the leaves' centroids; for colliders of edges
--- only, the length-weighted mean of their midpoints; of points only, their mean; (0, 0)
--- when empty.
---@return number x, number y
function Collider:getCentroid()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:getCentroid') end
  if not self._massOK then refreshMass(self) end
  return self[X], self[Y]
end

--- Area and centroid together.
---@return number area, number x, number y
function Collider:getAreaCentroid()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:getAreaCentroid') end
  if not self._massOK then refreshMass(self) end
  return self:getArea(), self[X], self[Y]
end

--- Radius of the smallest circle about the centroid that holds every leaf.
---@return number
function Collider:getRadius()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:getRadius') end
  if not self._clean then refresh(self) end
  local r = self[CRADIUS]
  if r < 0 then r = radius(self) end -- (a translation keeps it: see shift)
  return r
end

--- Bounds of all leaves as minimum x, minimum y, width, height; (0, 0, 0, 0) when empty.
---@return number x, number y, number w, number h
function Collider:getBbox()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:getBbox') end
  if not self._clean then refresh(self) end
  return self[MINX], self[MINY], self[MAXX] - self[MINX], self[MAXY] - self[MINY]
end

--- Bounds of all leaves as minimum x, minimum y, maximum x, maximum y.
---@return number minx, number miny, number maxx, number maxy
function Collider:getBounds()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:getBounds') end
  if not self._clean then refresh(self) end
  return self[MINX], self[MINY], self[MAXX], self[MAXY]
end

--- The angle: the sum of every rotation applied to this collider (or given to its
--- constructor, for single-shape colliders and Capsules).
---@return number
function Collider:getAngle()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:getAngle') end
  return self[CANGLE] or 0
end

--- Number of leaf shapes in the whole tree.
---@return integer
function Collider:getShapeCount()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:getShapeCount') end
  if self._nleaves < 0 then refreshLeaves(self) end
  return self._nleaves
end

--- The outermost collider holding this one (itself when it has no parent).
---@return strike.Collider
function Collider:getRoot()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:getRoot') end
  return Shape._rootOf(self)
end

--- The collider holding this one directly, or nil (the original Strike's `collider.parent`).
---@return strike.Collider|nil
function Collider:getParent()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:getParent') end
  return self._parent
end

-- Stateless leaf iterator: the control variable is the previous leaf.
-- (a previous leaf no longer in the collider, removed by the loop's body, ends the loop:
-- starting over would never end)
local function elemsIter(self, prev)
  if self._nleaves < 0 then refreshLeaves(self) end
  local i = 0
  if prev then
    i = self._leafPos[prev]
    if not i then return nil end
  end
  return self._leaves[i + 1]
end

--- Iterate over every leaf shape, nested or not, depth first in insertion order:
--- `for shape in collider:elems() do`. Allocates nothing once used (the first call makes the
--- table of positions it keeps). A loop that removes the leaf it is at ends there.
---@return function, strike.Collider, nil
function Collider:elems()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:elems') end
  if self._nleaves < 0 then refreshLeaves(self) end
  if not self._leafPos then -- (the leaves' positions, kept up to date by refreshLeaves from now on)
    local pos, leaves = {}, self._leaves
    for i = 1, self._nleaves do pos[leaves[i]] = i end
    self._leafPos = pos
  end
  return elemsIter, self, nil
end

--- Iterate over every leaf with its direct parent and its index in that parent:
--- `for parent, shape, index in collider:ipairs() do`. Makes one closure per call.
---@return function
function Collider:ipairs()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:ipairs') end
  if self._nleaves < 0 then refreshLeaves(self) end
  local leaves, i = self._leaves, 0
  return function()
    i = i + 1
    local s = leaves[i]
    if not s then return nil end
    local p = s._parent
    local shapes = p and p._shapes
    if not shapes or shapes[0] ~= p then badShapes(self, 'strike.Collider:ipairs') end
    for k = 1, #shapes do
      if shapes[k] == s then return p, s, k end
    end
    badShapes(self, 'strike.Collider:ipairs')
  end
end

--- Minimum and maximum of the projection of every leaf on the unit vector (nx, ny).
---@param nx number
---@param ny number
---@return number min, number max
function Collider:project(nx, ny)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:project') end
  number(nx, 'strike.Collider:project', 'nx')
  number(ny, 'strike.Collider:project', 'ny')
  if self._nleaves < 0 then refreshLeaves(self) end
  local lo, hi = huge, -huge
  local leaves = self._leaves
  for i = 1, self._nleaves do
    local a, b = leaves[i]:project(nx, ny)
    if a < lo then lo = a end
    if b > hi then hi = b end
  end
  return lo, hi
end

--- True when the point is strictly inside some leaf, or on a seam of one (a cut inside a
--- compound, such as those between the pieces of S.trikers.Concave: see `_seams` in
--- strike/base/VertexShape.lua), away from the seam's ends. A point of the outline is not
--- inside (touching is not inside). Takes x, y or {x = , y = }.
---@param x number|table
---@param y number|nil
---@return boolean
function Collider:containsPoint(x, y)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:containsPoint') end
  x, y = Shape._point(x, y, 'strike.Collider:containsPoint')
  if self._nleaves < 0 then refreshLeaves(self) end
  local leaves, n = self._leaves, self._nleaves
  for i = 1, n do
    if leaves[i]:containsPoint(x, y) then return true end
  end
  for i = 1, n do -- (a point on a cut is strictly inside no piece, yet inside the compound)
    local s = leaves[i]
    if s._seams and s:_onSeams(x, y) then return true end
  end
  return false
end

-- Leaf poses after a transform: `pose(leaf, a, b, c)` returns the new x, y and scale. They
-- read a leaf's position slots (what getCentroid returns, without its check of self).
local function moved(s, dx, dy)
  local x, y = s[X], s[Y]
  return x + dx, y + dy, s[SCALE]
end

local function rotated(s, a, rx, ry)
  local x, y = s[X], s[Y]
  local dx, dy = rotate(x - rx, y - ry, cos(a), sin(a))
  return rx + dx, ry + dy, s[SCALE]
end

local function scaled(s, sf, rx, ry)
  local x, y = s[X], s[Y]
  return rx + (x - rx) * sf, ry + (y - ry) * sf, s[SCALE] * sf
end

-- Give every leaf its new pose (and turn it by `turn`), or, when some leaf would leave
-- strike's limits (overflow, or lengths out of range: the test its constructor and its own
-- transforms apply, Shape._checkPose), raise an error at the caller's line before anything
-- moves.
local function eachLeaf(self, fname, pose, a, b, c, turn)
  if self._nleaves < 0 then refreshLeaves(self) end
  local leaves, n = self._leaves, self._nleaves
  for i = 1, n do
    local s = leaves[i]
    local x, y, k = pose(s, a, b, c)
    checkPose(s, x, y, k, fname)
  end
  for i = 1, n do
    local s = leaves[i]
    local x, y, k = pose(s, a, b, c)
    s:_place(x, y, k, turn)
  end
end

-- Call fn(c, x, y, z) on every collider held by `self` at any depth, `self` not included,
-- in no particular order, and go below only where `into(c)` (a walk with the shared stack: see
-- "Depth" above; fn must not change the tree).
local function eachBelow(self, into, fn, x, y, z, w)
  local base = top
  local n, c = base, self
  while true do
    local shapes = childrenOf(c, 'strike')
    for i = 1, #shapes do
      local child = shapes[i]
      if child._shapes and into(child) then
        fn(child, x, y, z, w)
        n = n + 1
        walk[n] = child
        top = n
      end
    end
    if n == base then break end
    c = walk[n]
    walk[n] = nil
    n = n - 1
  end
  top = base
end

local function always() return true end

local function turn(c, a) c[CANGLE] = (c[CANGLE] or 0) + a end

-- Add `a` to the angle of this collider and of every collider it holds (`depth` levels down
-- already: nil at the top; see SHALLOW).
local function addAngle(self, a, depth)
  self[CANGLE] = (self[CANGLE] or 0) + a
  if self._nleaves >= 0 and self._leaves == self._shapes then return end -- (no collider below)
  depth = depth or 0
  if depth >= SHALLOW then return eachBelow(self, always, turn, a) end
  local shapes = self._shapes -- (childrenOf written out)
  if type(shapes) ~= 'table' or shapes[0] ~= self then badShapes(self, 'strike') end
  for i = 1, #shapes do
    local child = shapes[i]
    if child._shapes then addAngle(child, a, depth + 1) end
  end
end

-- After every leaf of c moved by (dx, dy): c's area and centroid (when `mass`) and bounds
-- (when `bounds`), valid before the move, are valid again shifted by it, and so are those of
-- every collider nested in c that holds a leaf (valid too: see the invariant above). The
-- radius does not change. This saves a collider moved every frame the walk over its leaves
-- that recomputing them takes; its leaves' own world data still refresh when first used.
--
-- Of the sums, only the ones that decide the centroid are shifted: the area's when there is
-- area, else the length's when there are edges, else the leaves' centroids'. The others are
-- read by nothing until the next refreshMass recomputes them all: an enclosing collider that
-- holds c has area (or length) whenever c has, and uses its own first sums then too.
local function shiftOne(c, dx, dy, mass, bounds)
  if mass then
    c[X], c[Y] = c[X] + dx, c[Y] + dy
    local area = c[CAREA]
    if area > 0 then
      c[CAX], c[CAY] = c[CAX] + area * dx, c[CAY] + area * dy
    elseif c[CLEN] > 0 then
      c[CLX], c[CLY] = c[CLX] + c[CLEN] * dx, c[CLY] + c[CLEN] * dy
    else
      c[CSX], c[CSY] = c[CSX] + c[CCOUNT] * dx, c[CSY] + c[CCOUNT] * dy
    end
    c._massOK = true
  end
  if bounds then
    c[MINX], c[MINY], c[MAXX], c[MAXY] = c[MINX] + dx, c[MINY] + dy, c[MAXX] + dx, c[MAXY] + dy
    c._clean = true
  end
end

local function holdsLeaves(c) return c[CCOUNT] > 0 end

-- shiftOne on c (written out: every translation of a body comes here) and on every collider
-- it holds that holds a leaf (`depth` levels down already: nil at the top; see SHALLOW).
local function shift(c, dx, dy, mass, bounds, depth)
  if mass then
    c[X], c[Y] = c[X] + dx, c[Y] + dy
    local area = c[CAREA]
    if area > 0 then
      c[CAX], c[CAY] = c[CAX] + area * dx, c[CAY] + area * dy
    elseif c[CLEN] > 0 then
      c[CLX], c[CLY] = c[CLX] + c[CLEN] * dx, c[CLY] + c[CLEN] * dy
    else
      c[CSX], c[CSY] = c[CSX] + c[CCOUNT] * dx, c[CSY] + c[CCOUNT] * dy
    end
    c._massOK = true
  end
  if bounds then
    c[MINX], c[MINY], c[MAXX], c[MAXY] = c[MINX] + dx, c[MINY] + dy, c[MAXX] + dx, c[MAXY] + dy
    c._clean = true
  end
  if c._nleaves >= 0 then -- (a collider's leaf list, when current, tells when none is nested)
    if c._leaves == c._shapes then return end -- (its children are its leaves)
    local single = c._single
    if single and single._parent == c then return end -- (one leaf, a child)
  end
  depth = depth or 0
  if depth >= SHALLOW then return eachBelow(c, holdsLeaves, shiftOne, dx, dy, mass, bounds) end
  local shapes = c._shapes -- (childrenOf written out)
  if type(shapes) ~= 'table' or shapes[0] ~= c then badShapes(c, 'strike') end
  for i = 1, #shapes do
    local child = shapes[i]
    if child._shapes and child[CCOUNT] > 0 then shift(child, dx, dy, mass, bounds, depth + 1) end
  end
end

-- Translate every leaf by (dx, dy), keeping the caches that a translation only shifts.
local function translateBy(self, dx, dy, fname)
  if self._nleaves < 0 then refreshLeaves(self) end
  local mass, bounds = self._massOK, self._clean
  local s = self._single
  if s then -- (one leaf, the usual body: eachLeaf without its loops and calls)
    local x, y = s[X] + dx, s[Y] + dy
    local extent = abs(x) + abs(y) + s[RADIUS] * s[SCALE]
    if extent - extent ~= 0 then checkPose(s, x, y, s[SCALE], fname) end -- (checkPose's test: it raises)
    s[X], s[Y] = x, y -- (Shape:_place at the same scale)
    s:_touch()
  else
    eachLeaf(self, fname, moved, dx, dy)
  end
  if self._nleaves > 0 and (mass or bounds) then shift(self, dx, dy, mass, bounds) end
end

--- Move every shape by (dx, dy).
---@param dx number
---@param dy number
---@return self
function Collider:translate(dx, dy)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:translate') end
  if type(dx) ~= 'number' or dx - dx ~= 0 then number(dx, 'strike.Collider:translate', 'dx') end
  if type(dy) ~= 'number' or dy - dy ~= 0 then number(dy, 'strike.Collider:translate', 'dy') end
  translateBy(self, dx + 0.0, dy + 0.0, 'strike.Collider:translate')
  return self
end

--- Move so that the centroid is at (x, y).
---@param x number
---@param y number
---@return self
function Collider:translateTo(x, y)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:translateTo') end
  -- (number's checks written out, as in translate: a game calls this for every body every frame)
  if type(x) ~= 'number' or x - x ~= 0 then number(x, 'strike.Collider:translateTo', 'x') end
  if type(y) ~= 'number' or y - y ~= 0 then number(y, 'strike.Collider:translateTo', 'y') end
  if not self._massOK then refreshMass(self) end
  translateBy(self, x - self[X], y - self[Y], 'strike.Collider:translateTo')
  return self
end

--- Rotate by `angle` radians about (refx, refy), by default the centroid.
---@param angle number
---@param refx number|nil
---@param refy number|nil
---@return self
function Collider:rotate(angle, refx, refy)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:rotate') end
  number(angle, 'strike.Collider:rotate', 'angle')
  refx, refy = optPoint(refx, refy, 'strike.Collider:rotate')
  if not refx then refx, refy = self:getCentroid() end
  eachLeaf(self, 'strike.Collider:rotate', rotated, angle, refx, refy, angle)
  addAngle(self, angle)
  return self
end

--- Rotate to the absolute `angle` about (refx, refy), by default the centroid.
---@param angle number
---@param refx number|nil
---@param refy number|nil
---@return self
function Collider:rotateTo(angle, refx, refy)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:rotateTo') end
  number(angle, 'strike.Collider:rotateTo', 'angle')
  refx, refy = optPoint(refx, refy, 'strike.Collider:rotateTo')
  if not refx then refx, refy = self:getCentroid() end
  local a = angle - (self[CANGLE] or 0)
  eachLeaf(self, 'strike.Collider:rotateTo', rotated, a, refx, refy, a)
  addAngle(self, a)
  return self
end

--- Scale by `sf` (> 0) about (refx, refy), by default the centroid. Calls compose.
---@param sf number
---@param refx number|nil
---@param refy number|nil
---@return self
function Collider:scale(sf, refx, refy)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:scale') end
  positive(sf, 'strike.Collider:scale', 'factor')
  refx, refy = optPoint(refx, refy, 'strike.Collider:scale')
  if not refx then refx, refy = self:getCentroid() end
  eachLeaf(self, 'strike.Collider:scale', scaled, sf, refx, refy)
  return self
end

-- A copy of the collider `self` alone: its fields but for its links and caches (the slots
-- are copied, stale), and an empty list of children.
local function copyNode(self)
  local c = setmetatable({}, getmetatable(self))
  for k, v in pairs(self) do
    if k ~= '_parent' and k ~= '_shapes' and k ~= '_leaves' and k ~= '_leafPos' and k ~= '_single' and k ~= '_space'
      and k ~= '_sid' then
      c[k] = v
    end
  end
  c._nleaves, c._massOK, c._clean, c._single, c._shapes = -1, false, false, false, { [0] = c }
  return c
end

--- An independent deep copy of the same class (children copied, parent links rebuilt);
--- then, if given, moved so its centroid is at (x, y) and rotated to `angle`. strike's own
--- data is duplicated; the values of your own fields (an `entity`, say) are shared by
--- reference, not copied. The copy belongs to no collider.
---@param x number|nil
---@param y number|nil
---@param angle number|nil
---@return strike.Collider
function Collider:copy(x, y, angle)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:copy') end
  childrenOf(self, 'strike.Collider:copy')
  local c = copyNode(self)
  -- the tree below, a level at a time: a stack of (original, copy) pairs whose children are
  -- still to copy (a nested collider of a class with a copy of its own is copied by it)
  local base = top
  local n, src, dst = base, self, c
  while true do
    local shapes, list = childrenOf(src, 'strike.Collider:copy'), dst._shapes
    for i = 1, #shapes do
      local child = shapes[i]
      local copy
      if child._shapes and child.copy == Collider.copy then
        copy = copyNode(child)
        walk[n + 1], walk[n + 2] = child, copy
        n = n + 2
        top = n
      else
        copy = child:copy()
      end
      copy._parent = dst
      list[i] = copy
    end
    if n == base then break end
    src, dst = walk[n - 1], walk[n]
    walk[n - 1], walk[n] = nil, nil
    n = n - 2
  end
  top = base
  if x ~= nil or y ~= nil then
    number(x, 'strike.Collider:copy', 'x')
    number(y, 'strike.Collider:copy', 'y')
    c:translateTo(x, y)
  end
  if angle ~= nil then c:rotateTo(number(angle, 'strike.Collider:copy', 'angle')) end
  return c
end

--- Draw every shape of the collider with LÖVE in the current colour (strike/draw.lua,
--- loaded on first use; an error when LÖVE is not there).
---@param mode string|nil 'line' (default) or 'fill'
function Collider:draw(mode)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:draw') end
  require(ROOT .. '.draw').body(self, mode)
end

-- Merge adjacent convex polygons among the direct children of c wherever their union is
-- convex (see consolidate), and mark its caches stale.
local function mergeChildren(c)
  local shapes = c._shapes
  local merged = true
  while merged do
    merged = false
    for i = 1, #shapes - 1 do
      local a = shapes[i]
      if a.merge then
        for j = i + 1, #shapes do
          local b = shapes[j]
          local m = b.merge and a:merge(b)
          if m then
            a._parent, b._parent = nil, nil
            m._parent = c
            shapes[i] = m
            table.remove(shapes, j)
            merged = true
            break
          end
        end
      end
      if merged then break end
    end
  end
  c._nleaves, c._massOK, c._clean, c._single = -1, false, false, false
end

--- Merge adjacent convex polygons among the direct children wherever their union is
--- convex, in this collider and in every collider nested in it; the merged piece replaces
--- the first of the two in order. Circles and edges are left alone.
---@return self
function Collider:consolidate()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:consolidate') end
  childrenOf(self, 'strike.Collider:consolidate')
  -- every collider of the tree, breadth first into the shared stack (a merge changes only
  -- its own collider's children: the order does not matter)
  local base = top
  local n = base + 1
  walk[n] = self
  local k = n
  while k <= n do
    local shapes = childrenOf(walk[k], 'strike.Collider:consolidate')
    for i = 1, #shapes do
      if shapes[i]._shapes then
        n = n + 1
        walk[n] = shapes[i]
      end
    end
    k = k + 1
  end
  top = n
  for j = n, base + 1, -1 do
    mergeChildren(walk[j])
    walk[j] = nil
  end
  top = base
  invalidate(self)
  return self
end

-- Rays (strike/collide/ray.lua holds the algorithms) ------------------------------------

local ray = require(ROOT .. '.collide.ray')
local checkRay, checkSegment, checkMax = ray.checkRay, ray.checkSegment, ray.checkMax
local leavesIntersections, leavesIntersect, leavesRayCast, leavesSegmentCast = ray.leavesIntersections,
  ray.leavesIntersect, ray.leavesRayCast, ray.leavesSegmentCast

--- The hits of the ray from (x, y) along (dx, dy) on every leaf shape it hits: a new table
--- `{ [shape] = { t1, t2 } }` (`{ t1 }` for a single hit), each list as
--- shape:rayIntersections gives it, less the crossings of seams (the cuts inside a compound
--- such as S.trikers.Concave: only its outline is a surface); nil when no leaf is hit.
---@param x number
---@param y number
---@param dx number
---@param dy number
---@return table<strike.Shape, number[]>|nil
function Collider:rayIntersections(x, y, dx, dy)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:rayIntersections') end
  checkRay('strike.Collider:rayIntersections', x, y, dx, dy)
  if self._nleaves < 0 then refreshLeaves(self) end
  return leavesIntersections(self._leaves, self._nleaves, x, y, dx, dy)
end

--- True when the ray from (x, y) along (dx, dy) hits some leaf shape (crossings of seams
--- do not count; a ray starting inside a compound hits its outline on the way out).
--- Allocates nothing.
---@param x number
---@param y number
---@param dx number
---@param dy number
---@return boolean
function Collider:rayIntersects(x, y, dx, dy)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:rayIntersects') end
  checkRay('strike.Collider:rayIntersects', x, y, dx, dy)
  if self._nleaves < 0 then refreshLeaves(self) end
  return leavesIntersect(self._leaves, self._nleaves, x, y, dx, dy)
end

--- The first boundary point of any leaf along the ray from (x, y) along (dx, dy), at a
--- distance of at most maxDistance (default math.huge): distance, hit point, outward unit
--- normal and the leaf shape hit (on ties, the first in elems() order); nil when none.
--- Seams are not boundaries: from inside an S.trikers.Concave, the hit is where the ray
--- leaves its outline, with the piece that owns that outline edge. Allocates nothing.
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param maxDistance number|nil
---@return number|nil distance, number x, number y, number nx, number ny, strike.Shape shape
function Collider:rayCast(x, y, dx, dy, maxDistance)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:rayCast') end
  checkRay('strike.Collider:rayCast', x, y, dx, dy)
  maxDistance = checkMax('strike.Collider:rayCast', maxDistance)
  if self._nleaves < 0 then refreshLeaves(self) end
  return leavesRayCast(self._leaves, self._nleaves, x, y, dx, dy, maxDistance)
end

--- rayCast along the segment from (x1, y1) to (x2, y2): distance from (x1, y1), hit point,
--- normal and leaf shape of the first hit; nil when there is none or p1 == p2.
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
---@return number|nil distance, number x, number y, number nx, number ny, strike.Shape shape
function Collider:segmentCast(x1, y1, x2, y2)
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Collider:segmentCast') end
  checkSegment('strike.Collider:segmentCast', x1, y1, x2, y2)
  if self._nleaves < 0 then refreshLeaves(self) end
  return leavesSegmentCast(self._leaves, self._nleaves, x1, y1, x2, y2)
end

return Collider
