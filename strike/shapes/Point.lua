--- A point: a circle of radius 0, so it works wherever a shape does. A point strictly
--- inside a shape collides with it, and its MTV pushes it out to the nearest boundary; a
--- point never collides with another point or with an edge (neither has an inside).
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local Circle = require(ROOT .. '.shapes.Circle')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local AREA, RADIUS, SHORT = layout.AREA, layout.RADIUS, layout.SHORT
local badSelf, type = check.badSelf, type

---@class strike.Point : strike.Circle
local Point = Circle:extend()
Point.name = 'Point'

--- A point at (x, y).
---@param x number
---@param y number
function Point:new(x, y)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Point:new') end
  check.number(x, 'strike.Point', 'x')
  check.number(y, 'strike.Point', 'y')
  self[AREA], self[RADIUS], self[SHORT] = 0, 0, 0
  self:_setPose(x, y)
  self:_checkNew('strike.Point')
end

--- Arguments that rebuild the point as it is now: x, y.
---@return number, number
function Point:unpack()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:unpack') end
  return self:getCentroid()
end

return Point
