--- A line segment: two-sided, no area. The narrow phase treats it as a polygon with two
--- vertices and two edges (1: p1 to p2, 2: p2 to p1) whose normals point to either side.
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local VertexShape = require(ROOT .. '.base.VertexShape')
local check = require(ROOT .. '.check')

local number, fail = check.number, check.fail
local badSelf, type = check.badSelf, type

---@class strike.Edge : strike.VertexShape
local Edge = VertexShape:extend()
Edge.name = 'Edge'

--- A segment from (x1, y1) to (x2, y2); the endpoints must differ.
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
function Edge:new(x1, y1, x2, y2)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Edge:new') end
  number(x1, 'strike.Edge', 'x1')
  number(y1, 'strike.Edge', 'y1')
  number(x2, 'strike.Edge', 'x2')
  number(y2, 'strike.Edge', 'y2')
  if x1 == x2 and y1 == y2 then
    fail(('strike.Edge: the endpoints must differ, got (%s, %s) twice'):format(x1, y1))
  end
  local cx, cy = (x1 + x2) / 2, (y1 + y2) / 2
  local dx, dy = x2 - x1, y2 - y1
  if not check.finite(cx) or not check.finite(cy) or not check.finite(dx * dx + dy * dy) then
    fail('strike.Edge: coordinates too large')
  end
  self:_setVertices({ x1, x2 }, { y1, y2 }, 2, cx, cy, 0)
end

--- Length of the segment.
---@return number
function Edge:getLength()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Edge:getLength') end
  return 2 * self:getRadius()
end

--- The endpoints as they are now: x1, y1, x2, y2.
---@return number, number, number, number
function Edge:unpack()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:unpack') end
  local x1, y1 = self:getVertex(1)
  local x2, y2 = self:getVertex(2)
  return x1, y1, x2, y2
end

return Edge
