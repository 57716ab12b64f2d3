--- A capsule collider: one S.hapes.Capsule (a segment swept by a circle: exact, no seams).
--- (The seed's walkthrough builds a capsule from two circles and a rectangle; docs/extending.md
--- keeps it as the example of a custom collider.)
local ROOT = (...):match('^(.-)%.colliders%.[^%.]+$')
local Collider = require(ROOT .. '.colliders.Collider')
local CapsuleShape = require(ROOT .. '.shapes.Capsule')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local badSelf, badCollider, type = check.badSelf, check.badCollider, type

---@class strike.CapsuleCollider : strike.Collider
local Capsule = Collider:extend()
Capsule.name = 'Capsule'

--- A capsule centred on (x, y), `dx` wide and `dy` tall **including** both caps (dy >= dx;
--- the caps have radius dx / 2), turned by `angle`: S.hapes.Capsule's arguments. Its one
--- child is that shape.
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param angle number|nil
function Capsule:new(x, y, dx, dy, angle)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Capsule:new') end
  Collider.new(self, CapsuleShape(x, y, dx, dy, angle))
  self[layout.CANGLE] = self._shapes[1][layout.ANGLE]
end

--- Width and height (caps included), as they are now.
---@return number width, number height
function Capsule:getDimensions()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Capsule:getDimensions') end
  local s = (self:unpack())
  if not s or not s.getDimensions then return 0, 0 end
  return s:getDimensions()
end

return Capsule
