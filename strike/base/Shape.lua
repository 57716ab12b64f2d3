--- The abstract base of every shape: a pose (position of the centroid, angle, uniform
--- scale) and the transforms. Subclasses keep their geometry in local coordinates
--- (relative to the centroid, unrotated, unscaled) and cache world-space data, refreshed
--- lazily: a transform only marks the shape dirty. The world-space data is the shape's own
--- array part, laid out as strike/base/layout.lua says (bounds, position, radius, then
--- whatever the kind keeps), so that the narrow phase reads one table per shape.
---
--- What a shape class must provide is declared once, in Shape.INTERFACE below, and checked
--- when the class is registered (S.hapes.X = cls, or a file in shapes/), when an instance is
--- built, and when one is first used (added to a collider, or tested).
local ROOT = (...):match('^(.-)%.base%.[^%.]+$')
local Object = require(ROOT .. '.class')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local ANGLE, AREA, COS, DIRTY = layout.ANGLE, layout.AREA, layout.COS, layout.DIRTY
local RADIUS, SCALE, SHORT, SIN = layout.RADIUS, layout.SCALE, layout.SHORT, layout.SIN
local vec = require(ROOT .. '.vec')
local limits = require(ROOT .. '.limits')
local kinds = require(ROOT .. '.collide.dispatch').kind
local compat = require(ROOT .. '.compat')
local tnew, unpack = compat.tableNew, compat.unpack

local X, Y = layout.X, layout.Y
local MINX, MINY, MAXX, MAXY = layout.MINX, layout.MINY, layout.MAXX, layout.MAXY
local cos, sin, abs, huge = math.cos, math.sin, math.abs, math.huge
local MIN_LENGTH, MAX_LENGTH = limits.MIN_LENGTH, limits.MAX_LENGTH
local rotate = vec.rotate
local number, positive, optPoint, finite, fail = check.number, check.positive, check.optPoint, check.finite,
  check.fail
local badSelf, type = check.badSelf, type

---@class strike.Shape : strike.Object
---@field kind string the class's kind, how the narrow phase treats its instances: 'polygon', 'circle' or
--- 'chain' (a chain segment); a rounded instance's is 'rounded' (getKind)
---@field name string the class name, as S.hapes names it
---@field type string always 'shape'
local Shape = Object:extend()
Shape.type = 'shape'
Shape.name = 'Shape'
--- The class marker strike reads (an instance's `type`, `name` and `kind` are the game's to
--- set: strike reads those from the class, and its own fields start with `_`; see
--- strike/reserved.lua).
Shape._type = 'shape'
--- No face of a shape is a seam unless it has `_seams` of its own (base/VertexShape.lua).
Shape._seams = false

--- What every shape class must provide (the base class provides the transforms and the
--- getters of the pose). `kind` must name a kind registered in strike/collide/dispatch.lua.
Shape.INTERFACE = {
  'kind', '_refresh', '_farthest', 'project', 'containsPoint', 'getSupport', 'getVertices', 'getVertex',
  'getVertexCount', 'getEdge', 'ipairs', 'vecs', 'unpack',
}

-- Classes found complete, so that the check runs once per class.
local complete = setmetatable({}, { __mode = 'k' })

--- Raise an error at the caller's line unless the shape class `cls` provides every member
--- of Shape.INTERFACE and a registered kind. `what` names the class in the message.
---@param cls table
---@param what string
function Shape.checkClass(cls, what)
  if complete[cls] then return end
  for _, name in ipairs(Shape.INTERFACE) do
    if cls[name] == nil then
      fail(('%s lacks `%s`, which every shape class must provide (%s); extend a strike shape such as'
        .. ' S.hapes.ConvexPolygon or S.hapes.Circle'):format(what, name, table.concat(Shape.INTERFACE, ', ')))
    end
  end
  if not kinds[cls.kind] then
    fail(('%s has the kind %s, which no narrow phase is registered for'):format(what, check.describe(cls.kind)))
  end
  -- (a shape's `_seams` is its class's false unless it has faces marked (VertexShape.lua): put
  -- on the class itself, so that reading it from an instance goes one step up, not up the
  -- whole chain of classes)
  if rawget(cls, '_seams') == nil then rawset(cls, '_seams', false) end
  complete[cls] = true
end

-- The spaces bodies are in, each with its Space:_moved (strike/space/Space.lua fills it as
-- it adds bodies): a body's `_space` is checked against it, so that a game's value there is
-- an error naming the field (see Shape:_touch).
local spaces = setmetatable({}, { __mode = 'k' })
Shape._spaces = spaces

-- The failure path of Shape:_touch, Collider's invalidate and rootOf: a `_parent` that is no
-- collider, or a `_space` that is no space. Names the field (strike/reserved.lua).
local function badLink(body)
  local reserved = require(ROOT .. '.reserved')
  reserved.check('strike', 'the ' .. (reserved.classType(body) or 'body'), body)
  fail('strike: a body has a _parent or _space that strike did not set; ' .. reserved.RULE)
end
Shape._badLink = badLink

-- A counter that stamps every pose: a shape's `_pose` changes whenever it moves, so a
-- result computed for one pose can tell that it is stale (see S.ite).
local poses = 0

--- Set the pose: the centroid at (x, y), angle 0, scale 1, and lay out the header of the
--- world data (see layout.lua). Called by constructors, after any vertex records exist.
---@param x number
---@param y number
function Shape:_setPose(x, y)
  -- (a shape of an incomplete class would fail deep inside the first test that meets it;
  -- the message is made only for a class not yet found complete)
  local cls = getmetatable(self)
  if not complete[cls] then Shape.checkClass(cls, ('strike.%s: its class'):format(tostring(cls.name))) end
  -- an own copy of the class's kind (or of the one a rounded shape set): the dispatch reads
  -- it every test
  if rawget(self, '_kind') == nil then self._kind = cls.kind end
  if self[1] == nil then -- (a table not made by _alloc, which fills the header with zeros)
    for k = 1, layout.SHAPE_HEADER do
      if self[k] == nil then self[k] = 0 end -- (refreshed before any use: the shape starts dirty)
    end
  end
  self[X], self[Y] = x + 0.0, y + 0.0 -- (floats: see setPose)
  self[ANGLE], self[COS], self[SIN], self[SCALE] = 0, 1, 0, 1
  self[DIRTY] = true
  poses = poses + 1
  self._pose = poses
end

--- Put the centroid at (x, y) exactly, at construction (a subclass that knows its exact
--- centre, free of the round-off of the area-weighted centroid). The shape must be dirty.
---@param x number
---@param y number
function Shape:_placeCentroid(x, y) self[X], self[Y] = x + 0.0, y + 0.0 end

-- Zeros for Shape._slots and Shape._numbers to copy: as many as the largest shape of
-- VertexShape._alloc has slots.
local ZEROS = {}
for k = 1, layout.size(64) do ZEROS[k] = 0 end

--- A table for `m` numbers (zeros, or nil on LuaJIT) whose array part has room for m and no
--- more, so that filling it lays nothing out anew: on the VMs other than LuaJIT a table
--- filled from empty doubles its array part as it goes (18 numbers take 32 slots of 16 bytes
--- on Lua 5.4). Above a few hundred numbers, an empty table, which grows as it is filled.
---@param m integer
---@return table
function Shape._numbers(m)
  if tnew then return tnew(m, 0) end
  if m <= #ZEROS then return { unpack(ZEROS, 1, m) } end
  return {}
end

-- Whether the next shape made is for a single-shape collider (Shape._forCollider).
local forCollider = false

--- An empty shape with `size` array slots and room for its named fields, so that no table
--- grows while it is built or used: a table that grows is laid out anew, which costs garbage
--- and gives LuaJIT's compiled field reads two layouts of one class to guard against; and the
--- new layout rounds its array part up to a power of two (64 slots on LuaJIT and Lua 5.4 for a
--- rectangle's 43). Its named fields: `_pose`, `_kind`, `_l` (or none of a circle's) and its
--- link, `_parent` in a collider or a space's `_space` and `_sid` (strike/reserved.lua): room
--- for 8, or for 4 when the shape is made for a single-shape collider (Shape._forCollider), which
--- keeps it. LuaJIT: table.new, its slots nil. The other VMs size a table only from a
--- constructor: this one has the slots as zeros (copied by the last expression, which sizes the
--- array part exactly) and names the fields (nil: it holds none of them yet, but its hash part
--- is made for them; Lua 5.1 keeps those names in it, so they are the ones strike sets).
---@param size integer
---@return table
function Shape._slots(size)
  if forCollider then
    forCollider = false
    if tnew then return tnew(size, 4) end
    return { _pose = nil, _kind = nil, _l = nil, _parent = nil, unpack(ZEROS, 1, size) }
  end
  if tnew then return tnew(size, 8) end
  return { _pose = nil, _kind = nil, _l = nil, _parent = nil, _space = nil, _sid = nil, _seams = nil,
    unpack(ZEROS, 1, size) }
end

--- (internal) Say whether the next shape made (its Shape._slots) is for a single-shape
--- collider, which keeps it in its list and gives it no other link: room for 4 named fields
--- then (colliders/single.lua, which says so just before it makes the shape, and that it is
--- done just after). A shape that has more fields after all (taken out of the collider and
--- added to a space) grows, as a table does, and is none the worse.
---@param yes boolean
function Shape._forCollider(yes) forCollider = yes end

--- The empty instance `Class(...)` fills (class.lua): room for the slots every shape has
--- (layout.lua) and for its few named fields (Shape._slots). Kinds with vertex records ask
--- for more (VertexShape).
---@return table
function Shape._alloc() return Shape._slots(layout.SHAPE_HEADER) end

--- What the slot SHORT measures (layout.lua: a shape's shortest length), for error messages.
Shape._shortName = 'shortest length'

-- Why the shape at this scale is outside strike's limits on lengths (limits.lua), or nil.
-- `is` is the verb of the message ('is', 'would be').
local function sizeError(self, scale, is)
  local size = self[RADIUS] * scale
  if not (size <= MAX_LENGTH) then -- luacheck: ignore 581 (NaN is too large)
    return ('too large: its radius (from the centroid to the farthest point) %s %s, above %s, the largest'
      .. ' length strike accepts'):format(is, check.describe(size), check.describe(MAX_LENGTH))
  end
  local short = self[SHORT] * scale
  if short < MIN_LENGTH and self[SHORT] > 0 then
    return ('too small: its %s %s %s, below %s, the smallest length strike accepts (its square must stay a'
      .. ' normal double)'):format(self._shortName, is, check.describe(short), check.describe(MIN_LENGTH))
  end
  return nil
end

--- Raise an error at the caller's line unless a newly built shape (pose at scale 1) is
--- within strike's limits (limits.lua): lengths from MIN_LENGTH to MAX_LENGTH, and
--- |x| + |y| + radius finite. Constructors call it once the geometry is set; a transform
--- applies the same test to the pose it would make (Shape._checkPose).
---@param fname string the constructor's name, for the message
function Shape:_checkNew(fname)
  local err = sizeError(self, 1, 'is')
  if err then fail(fname .. ': ' .. err) end
  if not finite(abs(self[X]) + abs(self[Y]) + self[RADIUS]) then
    fail(fname .. ': coordinates too large (|x| + |y| + radius must stay finite)')
  end
end

--- Raise an error at the caller's line unless the pose (x, y, scale) keeps the shape within
--- strike's limits, as its constructor would demand (see Shape:_checkNew): every world
--- coordinate finite, and, when the scale changes, every length from MIN_LENGTH to
--- MAX_LENGTH (the area, at most about the radius squared, then stays finite too).
--- `fname` names the transform. Changes nothing.
---@param s strike.Shape
---@param x number
---@param y number
---@param scale number
---@param fname string
function Shape._checkPose(s, x, y, scale, fname)
  if scale ~= s[SCALE] then
    if not (scale > 0) then fail(fname .. ': the scale would underflow to 0') end -- luacheck: ignore 581
    if scale == huge then fail(fname .. ': the scale would overflow') end
    local err = sizeError(s, scale, 'would be')
    if err then fail(fname .. ': the result would be ' .. err) end
  end
  if not finite(abs(x) + abs(y) + s[RADIUS] * scale) then
    fail(fname .. ': the result would overflow (coordinates too large)')
  end
end
local checkPose = Shape._checkPose

-- Commit a new pose if it keeps the shape within strike's limits; otherwise raise an error
-- and leave the shape as it was. The position is stored as floats: on Lua 5.3+ integer
-- coordinates would make every product of them integer arithmetic, which wraps around past
-- 2^63 (a circle 5e9 away got the normal (1.95, 0)).
local function setPose(self, x, y, scale, fname)
  checkPose(self, x, y, scale, fname)
  self[X], self[Y], self[SCALE] = x + 0.0, y + 0.0, scale
end

--- Set the pose to a position and scale already checked (a collider moving its leaves),
--- turned by `turn` radians when given, and mark the shape moved.
---@param x number
---@param y number
---@param scale number
---@param turn number|nil
function Shape:_place(x, y, scale, turn)
  self[X], self[Y], self[SCALE] = x, y, scale
  if turn then
    local angle = self[ANGLE] + turn
    self[ANGLE], self[COS], self[SIN] = angle, cos(angle), sin(angle)
  end
  self:_touch()
end

--- Mark this shape's world-space cache, and every enclosing collider's area, centroid,
--- bounds and radius, as stale, and stamp the new pose. The walk stops at the first
--- collider already marked (see the cache protocol in colliders/Collider.lua).
---
--- A body in a space (strike/space/Space.lua) hears of it: the walk that reaches the root
--- queues it there. The walk always reaches the root of a body the space has refreshed
--- since its last move, since refreshing it cleans every collider in it; when it stops
--- earlier, the root was already stale, so already queued.
---
--- (A `_parent` or `_space` a game changed is an error here: every collider has flags, true
--- or false, so a parent without them is none; a space is one `spaces` knows.)
function Shape:_touch()
  self[DIRTY] = true
  poses = poses + 1
  self._pose = poses
  local p = self._parent
  if not p then
    local space = self._space
    if space then
      local moved = spaces[space]
      if not moved then badLink(self) end
      moved(space, self)
    end
    return
  end
  while p and (p._massOK or p._clean) do
    p._massOK, p._clean = false, false
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
  if p and p._clean == nil then badLink(self) end
end

--- Move by (dx, dy).
---@param dx number
---@param dy number
---@return self
function Shape:translate(dx, dy)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:translate') end
  -- (the checks of number and setPose written out: a game calls this for every body every
  -- frame, and an interpreter pays for each call; the errors are theirs)
  if type(dx) ~= 'number' or dx - dx ~= 0 then number(dx, 'strike.Shape:translate', 'dx') end
  if type(dy) ~= 'number' or dy - dy ~= 0 then number(dy, 'strike.Shape:translate', 'dy') end
  local x, y = self[X] + dx, self[Y] + dy
  if abs(x) + abs(y) + self[RADIUS] * self[SCALE] == huge then
    setPose(self, x, y, self[SCALE], 'strike.Shape:translate') -- (raises the error)
  end
  self[X], self[Y] = x + 0.0, y + 0.0
  self:_touch()
  return self
end

--- Move the centroid to (x, y).
---@param x number
---@param y number
---@return self
function Shape:translateTo(x, y)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:translateTo') end
  if type(x) ~= 'number' or x - x ~= 0 then number(x, 'strike.Shape:translateTo', 'x') end
  if type(y) ~= 'number' or y - y ~= 0 then number(y, 'strike.Shape:translateTo', 'y') end
  if abs(x) + abs(y) + self[RADIUS] * self[SCALE] == huge then
    setPose(self, x, y, self[SCALE], 'strike.Shape:translateTo') -- (raises the error)
  end
  self[X], self[Y] = x + 0.0, y + 0.0
  self:_touch()
  return self
end

-- Rotate the pose by `a` about (rx, ry) (the centroid when nil). Arguments are valid.
local function rotateBy(self, a, rx, ry, fname)
  if rx then
    local dx, dy = rotate(self[X] - rx, self[Y] - ry, cos(a), sin(a))
    setPose(self, rx + dx, ry + dy, self[SCALE], fname)
  end
  local angle = self[ANGLE] + a
  self[ANGLE], self[COS], self[SIN] = angle, cos(angle), sin(angle)
  self:_touch()
  return self
end

--- Rotate by `angle` radians (positive turns +x toward +y, as love.graphics.rotate does)
--- about (refx, refy), by default the centroid.
---@param angle number
---@param refx number|nil
---@param refy number|nil
---@return self
function Shape:rotate(angle, refx, refy)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:rotate') end
  number(angle, 'strike.Shape:rotate', 'angle')
  refx, refy = optPoint(refx, refy, 'strike.Shape:rotate')
  return rotateBy(self, angle, refx, refy, 'strike.Shape:rotate')
end

--- Rotate to the absolute `angle` about (refx, refy), by default the centroid: the same
--- as rotate(angle - getAngle(), refx, refy).
---@param angle number
---@param refx number|nil
---@param refy number|nil
---@return self
function Shape:rotateTo(angle, refx, refy)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:rotateTo') end
  number(angle, 'strike.Shape:rotateTo', 'angle')
  refx, refy = optPoint(refx, refy, 'strike.Shape:rotateTo')
  return rotateBy(self, angle - self[ANGLE], refx, refy, 'strike.Shape:rotateTo')
end

--- Scale by factor `sf` (> 0) about (refx, refy), by default the centroid. Calls compose:
--- scale(2) then scale(3) is scale(6).
---@param sf number
---@param refx number|nil
---@param refy number|nil
---@return self
function Shape:scale(sf, refx, refy)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:scale') end
  positive(sf, 'strike.Shape:scale', 'factor')
  refx, refy = optPoint(refx, refy, 'strike.Shape:scale')
  local x, y = self[X], self[Y]
  if refx then x, y = refx + (x - refx) * sf, refy + (y - refy) * sf end
  setPose(self, x, y, self[SCALE] * sf, 'strike.Shape:scale')
  self:_touch()
  return self
end

--- The angle in radians: the constructor's angle plus every rotation since.
---@return number
function Shape:getAngle()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getAngle') end
  return self[ANGLE]
end

--- The accumulated scale factor (1 after construction).
---@return number
function Shape:getScale()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getScale') end
  return self[SCALE]
end

--- The centroid (area centroid for polygons, centre for circles, midpoint for edges).
---@return number x, number y
function Shape:getCentroid()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getCentroid') end
  return self[X], self[Y]
end

--- The area (never negative; 0 for an Edge).
---@return number
function Shape:getArea()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getArea') end
  return self[AREA] * self[SCALE] * self[SCALE]
end

--- Area and centroid together.
---@return number area, number x, number y
function Shape:getAreaCentroid()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getAreaCentroid') end
  return self:getArea(), self[X], self[Y]
end

--- Radius of the smallest circle about the centroid that holds the shape.
---@return number
function Shape:getRadius()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getRadius') end
  return self[RADIUS] * self[SCALE]
end

--- Axis-aligned bounds as minimum x, minimum y, width, height.
---@return number x, number y, number w, number h
function Shape:getBbox()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getBbox') end
  if self[DIRTY] then self:_refresh() end
  return self[MINX], self[MINY], self[MAXX] - self[MINX], self[MAXY] - self[MINY]
end

--- Axis-aligned bounds as minimum x, minimum y, maximum x, maximum y.
---@return number minx, number miny, number maxx, number maxy
function Shape:getBounds()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getBounds') end
  if self[DIRTY] then self:_refresh() end
  return self[MINX], self[MINY], self[MAXX], self[MAXY]
end

-- The outermost collider holding `node`, a shape or a collider, or `node` itself: getRoot
-- without its check of `self`, for S.AT and S.triking.
-- (every collider has its flag `_clean`: a `_parent` without one is a game's value)
local function rootOf(node)
  local up = node._parent
  while up do
    if up._clean == nil then badLink(node) end
    node = up
    up = node._parent
  end
  return node
end
Shape._rootOf = rootOf

--- The outermost collider that holds this shape, or the shape itself when it has none.
---@return strike.Shape|strike.Collider
function Shape:getRoot()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getRoot') end
  return rootOf(self)
end

--- The collider holding this shape directly, or nil (the original Strike's `shape.parent`).
---@return strike.Collider|nil
function Shape:getParent()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getParent') end
  return self._parent
end

--- The kind the narrow phase treats this shape as: its class's `kind` ('polygon', 'circle',
--- 'chain', or one a game registers), or 'rounded' for a rounded polygon (a capsule, a
--- rectangle or polygon with a radius).
---@return string
function Shape:getKind()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getKind') end
  return self._kind
end

--- An independent copy of the same class, in the same pose; then, if given, moved so its
--- centroid is at (x, y) and rotated to `angle`. Works for user-defined shapes too: it
--- copies the shape's fields instead of calling the constructor. strike's own data is
--- duplicated; the values of your own fields (an `entity`, say) are shared by reference,
--- not copied. The copy belongs to no collider.
---@param x number|nil
---@param y number|nil
---@param angle number|nil
---@return strike.Shape
function Shape:copy(x, y, angle)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:copy') end
  local c = setmetatable({}, getmetatable(self))
  for k = 1, #self do c[k] = self[k] end -- (the array part first, so it stays an array)
  for k, v in pairs(self) do
    -- (rawget: an own field may shadow the class's; a copy is in no space)
    if rawget(c, k) == nil and k ~= '_parent' and k ~= '_space' and k ~= '_sid' then c[k] = v end
  end
  -- (local geometry is never changed after construction, so copies share it)
  c[DIRTY] = true
  poses = poses + 1
  c._pose = poses
  if x ~= nil or y ~= nil then
    number(x, 'strike.Shape:copy', 'x')
    number(y, 'strike.Shape:copy', 'y')
    c:translateTo(x, y)
  end
  if angle ~= nil then c:rotateTo(number(angle, 'strike.Shape:copy', 'angle')) end
  return c
end

--- Point-containment accepts (x, y) or a table {x = , y = }.
---@return number|nil, number|nil
function Shape._point(x, y, fname)
  if type(x) == 'table' then x, y = x.x, x.y end
  number(x, fname, 'point x')
  number(y, fname, 'point y')
  return x, y
end

--- Draw the shape with LÖVE in the current colour (strike/draw.lua, loaded on first use;
--- an error when LÖVE is not there).
---@param mode string|nil 'line' (default) or 'fill'
function Shape:draw(mode)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:draw') end
  require(ROOT .. '.draw').body(self, mode)
end

-- Rays (strike/collide/ray.lua holds the algorithms) ------------------------------------

local ray = require(ROOT .. '.collide.ray')
local checkRay, checkSegment, checkMax, checkTs = ray.checkRay, ray.checkSegment, ray.checkMax, ray.checkTs
local rayIntersections, rayIntersects, rayCast, segmentCast = ray.intersections, ray.intersects, ray.rayCast,
  ray.segmentCast

--- Where the ray from (x, y) along (dx, dy) crosses the boundary: distances along the
--- normalised direction (any non-zero length is accepted), ascending, none behind the
--- origin. Two for a ray that passes through; one for a graze or tangent, for a ray
--- starting inside (its exit) and for an Edge it crosses; a collinear ray on an Edge gives
--- the overlap's ends. Fills `ts` from index 1 (entries past n cleared; nothing allocated) or a new table.
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param ts number[]|nil
---@return number[]|nil ts, integer n the list and the count; nil, 0 when the ray misses
function Shape:rayIntersections(x, y, dx, dy, ts)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:rayIntersections') end
  checkRay('strike.Shape:rayIntersections', x, y, dx, dy)
  if ts ~= nil and type(ts) ~= 'table' then checkTs('strike.Shape:rayIntersections', ts) end
  return rayIntersections(self, x, y, dx, dy, ts)
end

--- True when the ray from (x, y) along (dx, dy) hits the shape (exactly when
--- rayIntersections returns a list). Allocates nothing.
---@param x number
---@param y number
---@param dx number
---@param dy number
---@return boolean
function Shape:rayIntersects(x, y, dx, dy)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:rayIntersects') end
  checkRay('strike.Shape:rayIntersects', x, y, dx, dy)
  return rayIntersects(self, x, y, dx, dy)
end

--- The first boundary point of the ray from (x, y) along (dx, dy) at a distance of at
--- most maxDistance (default math.huge): distance, hit point and the outward unit normal
--- there; nil when there is none. A ray starting inside reports its exit. The normal is
--- the face that bounds the ray's interval at that end (at a vertex: the entering face;
--- on ties, the lower-numbered face); a circle's is (hit - centre) / r. An Edge's normal
--- faces the ray's origin; for a ray along the Edge it is the segment's direction at the
--- end hit. Allocates nothing.
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param maxDistance number|nil
---@return number|nil distance, number x, number y, number nx, number ny
function Shape:rayCast(x, y, dx, dy, maxDistance)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:rayCast') end
  checkRay('strike.Shape:rayCast', x, y, dx, dy)
  return rayCast(self, x, y, dx, dy, checkMax('strike.Shape:rayCast', maxDistance))
end

--- rayCast along the segment from (x1, y1) to (x2, y2): the first hit on the segment, its
--- distance from (x1, y1) in units of length; nil when there is none or p1 == p2.
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
---@return number|nil distance, number x, number y, number nx, number ny
function Shape:segmentCast(x1, y1, x2, y2)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:segmentCast') end
  checkSegment('strike.Shape:segmentCast', x1, y1, x2, y2)
  return segmentCast(self, x1, y1, x2, y2)
end

return Shape
