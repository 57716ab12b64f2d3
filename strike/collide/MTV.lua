--- The result of a collision test: the minimum translation vector and who it belongs to.
---
--- Orientation: for S.AT(a, b) and S.triking(a, b) the vector points from the first
--- argument toward the second, so moving the second by +(x, y), or the first by -(x, y),
--- separates them (they end up exactly touching).
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local Object = require(ROOT .. '.class')
local check = require(ROOT .. '.check')
local badSelf, type = check.badSelf, type

local limits = require(ROOT .. '.limits')

---@class strike.MTV : strike.Object
---@field x number translation vector, x: normal times depth when colliding; when separating, the
--- separating axis times the gap found along it (a lower bound of the distance)
---@field y number translation vector, y
---@field nx number unit normal, x, from the first argument toward the second (also set when separating)
---@field ny number unit normal, y
---@field depth number penetration depth, > 0 when colliding; when separating, minus the gap (<= 0)
---@field separating boolean true when the shapes do not collide (touching is not colliding)
---@field collider table|false outermost collider of the first argument (the shape itself if it has none)
---@field collided table|false outermost collider of the second argument
---@field colliderShape strike.Shape|false the leaf shape of the first argument (false in a blank MTV;
--- for bodies with several members, the member whose pair gave the answer)
---@field collidedShape strike.Shape|false the leaf shape of the second argument
---@field edgeIndex integer i > 0: edge i of colliderShape gave the axis; -j: edge j of collidedShape
--- did; 0: the axis came from a circle (centre to centre, or centre to a vertex), from two rounded
--- shapes' corners (core vertex to core vertex), or from the outline rule's search (outline.lua)
local MTV = Object:extend()
MTV.name = 'MTV'
MTV.type = 'mtv'
MTV._type = 'mtv' -- (the class marker strike reads: strike/reserved.lua)

--- A new MTV: vector (dx, dy) (default 0, 0) between two shapes.
---@param dx number|nil
---@param dy number|nil
---@param colliderShape strike.Shape|nil
---@param collidedShape strike.Shape|nil
---@param separating boolean|nil
function MTV:new(dx, dy, colliderShape, collidedShape, separating)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.MTV:new') end
  dx = check.optNumber(dx, 'strike.MTV', 'dx', 0)
  dy = check.optNumber(dy, 'strike.MTV', 'dy', 0)
  local nx, ny, l = limits.unit(dx, dy) -- (unit even for tiny or huge vectors: limits.lua)
  if not nx then nx, ny, l = 0, 0, 0 end
  separating = separating and true or false
  -- Every field is set, always in this order (false for a missing shape), so that every
  -- MTV has the same table layout: LuaJIT then compiles one trace for all of them.
  self.x, self.y = dx, dy
  self.nx, self.ny = nx, ny
  self.depth = separating and -l or l
  self.separating = separating
  self.edgeIndex = 0
  self.colliderShape, self.collidedShape = colliderShape or false, collidedShape or false
  self.collider, self.collided = colliderShape or false, collidedShape or false
  -- The poses of the two shapes the vector was computed for (see S.ite).
  self._poseA = type(colliderShape) == 'table' and colliderShape._pose or false
  self._poseB = type(collidedShape) == 'table' and collidedShape._pose or false
end

--- Length of the vector.
---@return number
function MTV:mag()
  if type(self) ~= 'table' or self._type ~= 'mtv' then badSelf(self, 'strike.MTV:mag') end
  return limits.length(self.x, self.y)
end

--- Squared length of the vector.
---@return number
function MTV:mag2()
  if type(self) ~= 'table' or self._type ~= 'mtv' then badSelf(self, 'strike.MTV:mag2') end
  return self.x * self.x + self.y * self.y
end

--- Multiply the vector by s (the normal and depth are left as they are).
---@param s number
---@return self
function MTV:scale(s)
  if type(self) ~= 'table' or self._type ~= 'mtv' then badSelf(self, 'strike.MTV:scale') end
  check.number(s, 'strike.MTV:scale', 'factor')
  self.x, self.y = self.x * s, self.y * s
  return self
end

--- Set `collider`, the outermost body of the first side; returns the MTV.
---@param collider table
---@return self
function MTV:setCollider(collider)
  if type(self) ~= 'table' or self._type ~= 'mtv' then badSelf(self, 'strike.MTV:setCollider') end
  self.collider = collider
  return self
end
--- Set `collided`, the outermost body of the second side; returns the MTV.
---@param collided table
---@return self
function MTV:setCollided(collided)
  if type(self) ~= 'table' or self._type ~= 'mtv' then badSelf(self, 'strike.MTV:setCollided') end
  self.collided = collided
  return self
end
--- Set `colliderShape`, the leaf shape of the first side; returns the MTV.
---@param shape strike.Shape
---@return self
function MTV:setColliderShape(shape)
  if type(self) ~= 'table' or self._type ~= 'mtv' then badSelf(self, 'strike.MTV:setColliderShape') end
  self.colliderShape = shape
  return self
end
--- Set `collidedShape`, the leaf shape of the second side; returns the MTV.
---@param shape strike.Shape
---@return self
function MTV:setCollidedShape(shape)
  if type(self) ~= 'table' or self._type ~= 'mtv' then badSelf(self, 'strike.MTV:setCollidedShape') end
  self.collidedShape = shape
  return self
end
--- Set `edgeIndex` (i: edge i of colliderShape gave the axis, -j: edge j of collidedShape, 0:
--- neither); returns the MTV.
---@param index integer
---@return self
function MTV:setEdgeIndex(index)
  if type(self) ~= 'table' or self._type ~= 'mtv' then badSelf(self, 'strike.MTV:setEdgeIndex') end
  self.edgeIndex = index
  return self
end
--- Set `separating` (any true value as true, nil and false as false); returns the MTV.
---@param separating boolean
---@return self
function MTV:setSeparating(separating)
  if type(self) ~= 'table' or self._type ~= 'mtv' then badSelf(self, 'strike.MTV:setSeparating') end
  self.separating = separating and true or false
  return self
end

-- Copy every field of the MTV `other` into the table `self`: MTV:set without its checks,
-- for S.triking, whose `out` may be a plain table.
local function copy(self, other)
  self.x, self.y, self.nx, self.ny, self.depth = other.x, other.y, other.nx, other.ny, other.depth
  self.separating, self.edgeIndex = other.separating, other.edgeIndex
  self.collider, self.collided = other.collider, other.collided
  self.colliderShape, self.collidedShape = other.colliderShape, other.collidedShape
  self._poseA, self._poseB = other._poseA or false, other._poseB or false
  return self
end
MTV._set = copy

-- Let go of the shapes and bodies an MTV names (its numbers stay): strike's own scratch and
-- pooled MTVs, so that they keep no body of the game's alive.
function MTV._letGo(m)
  m.colliderShape, m.collidedShape, m.collider, m.collided = false, false, false, false
end

--- Copy every field of `other` into this MTV.
---@param other strike.MTV
---@return self
function MTV:set(other)
  if type(self) ~= 'table' or self._type ~= 'mtv' then badSelf(self, 'strike.MTV:set') end
  if type(other) ~= 'table' or type(other.x) ~= 'number' or type(other.y) ~= 'number' then
    check.fail(('strike.MTV:set: argument 1 must be an MTV, got %s'):format(check.describe(other)))
  end
  return copy(self, other)
end

return MTV
