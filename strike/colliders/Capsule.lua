--- A capsule (stadium): a rectangle with a half-disc on each end.
local ROOT = (...):match('^(.-)%.colliders%.[^%.]+$')
local Collider = require(ROOT .. '.colliders.Collider')
local Circle = require(ROOT .. '.shapes.Circle')
local Rectangle = require(ROOT .. '.shapes.Rectangle')
local check = require(ROOT .. '.check')
local badSelf, badCollider, type = check.badSelf, check.badCollider, type
local limits = require(ROOT .. '.limits')

local sqrt, pi = math.sqrt, math.pi
local MIN_LENGTH, MAX_LENGTH = limits.MIN_LENGTH, limits.MAX_LENGTH

-- Raise an error at the caller's line: `what` (value v) is out of strike's limits on
-- lengths (strike/limits.lua), below (`least`) or above `bound`. A capsule's members must
-- be shapes strike accepts: caps of radius dx / 2 and a rectangle dy - dx tall, each
-- length from MIN_LENGTH to MAX_LENGTH.
local function refuse(what, v, bound, least)
  check.fail(('strike.Capsule: %s too %s: got %s, %s %s (strike accepts lengths from %s to %s)'):format(what,
    least and 'small' or 'large', check.describe(v), least and 'below' or 'above', check.describe(bound),
    check.describe(MIN_LENGTH), check.describe(MAX_LENGTH)))
end

---@class strike.Capsule : strike.Collider
local Capsule = Collider:extend()
Capsule.name = 'Capsule'

--- A capsule centred on (x, y), `dx` wide and `dy` tall **including** both caps
--- (dy >= dx; the caps have radius dx / 2), turned by `angle`. Unrotated, the caps sit
--- on the vertical axis. Children: the two cap circles (-y end first), then the
--- rectangle between them (none when dy == dx: the capsule is then one circle).
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param angle number|nil
function Capsule:new(x, y, dx, dy, angle)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Capsule:new') end
  check.number(x, 'strike.Capsule', 'x')
  check.number(y, 'strike.Capsule', 'y')
  check.positive(dx, 'strike.Capsule', 'width')
  check.positive(dy, 'strike.Capsule', 'height')
  angle = check.optNumber(angle, 'strike.Capsule', 'angle', 0)
  if dy < dx then
    check.fail(('strike.Capsule: height (caps included) must be at least the width, got width %s and height %s')
      :format(dx, dy))
  end
  -- (its members must be shapes strike accepts: see refuse above)
  if dx / 2 < MIN_LENGTH then refuse('width (twice the caps\' radius)', dx, 2 * MIN_LENGTH, true) end
  -- (the largest radius of a member: a cap's, or the rectangle's half diagonal)
  local size = limits.length(dx, dy - dx) / 2
  if not (size <= MAX_LENGTH) then -- luacheck: ignore 581 (NaN is too large)
    refuse('size (the radius of its largest member, the rectangle between the caps)', size, MAX_LENGTH, false)
  end
  if dy > dx and dy - dx < MIN_LENGTH then
    refuse('straight part (height - width, when not 0)', dy - dx, MIN_LENGTH, true)
  end
  Collider.new(self)
  local r, h = dx / 2, (dy - dx) / 2
  if h > 0 then
    self:add(Circle(x, y - h, r), Circle(x, y + h, r), Rectangle(x, y, dx, dy - dx))
  else
    self:add(Circle(x, y, r))
  end
  if angle ~= 0 then self:rotate(angle) end
end

-- Cap radius and the distance between the cap centres, from the current leaves.
local function caps(self)
  local a, b = self.shapes[1], self.shapes[2]
  if not a or a.kind ~= 'circle' then return nil end
  if not b or b.kind ~= 'circle' then return a:getRadius(), 0 end
  local ax, ay = a:getCentroid()
  local bx, by = b:getCentroid()
  local dx, dy = bx - ax, by - ay
  return a:getRadius(), sqrt(dx * dx + dy * dy)
end

--- The capsule's true area, pi r^2 + 2 r L (its members overlap, so the sum of their areas
--- would count the caps twice).
---@return number
function Capsule:getArea()
  if type(self) ~= 'table' or self.shapes == nil then badCollider(self, 'strike.Collider:getArea') end
  local r, l = caps(self)
  if not r then return Collider.getArea(self) end
  return pi * r * r + 2 * r * l
end

--- Area and centroid together.
---@return number area, number x, number y
function Capsule:getAreaCentroid()
  if type(self) ~= 'table' or self.shapes == nil then badCollider(self, 'strike.Collider:getAreaCentroid') end
  local x, y = self:getCentroid()
  return self:getArea(), x, y
end

--- Width and height (caps included), as they are now.
---@return number width, number height
function Capsule:getDimensions()
  if type(self) ~= 'table' or self.shapes == nil then badCollider(self, 'strike.Capsule:getDimensions') end
  local r, l = caps(self)
  if not r then return 0, 0 end
  return 2 * r, 2 * r + l
end

return Capsule
