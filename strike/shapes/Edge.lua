--- A line segment: two-sided, no area. The narrow phase treats it as a polygon with two
--- vertices and two edges (1: p1 to p2, 2: p2 to p1) whose normals point to either side.
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local VertexShape = require(ROOT .. '.base.VertexShape')
local check = require(ROOT .. '.check')
local limits = require(ROOT .. '.limits')

local badSelf, type = check.badSelf, type
local huge = math.huge
local number, fail, describe = check.number, check.fail, check.describe
local MIN_LENGTH, MAX_LENGTH = limits.MIN_LENGTH, limits.MAX_LENGTH

---@class strike.Edge : strike.VertexShape
local Edge = VertexShape:extend()
Edge.name = 'Edge'
Edge._alloc = VertexShape._alloc2

--- Raise an error at the caller's line unless the segment from (x1, y1) to (x2, y2) (finite
--- coordinates) has a length strike accepts (limits.lua): at least MIN_LENGTH (the test
--- Shape:_checkNew makes on the shortest edge, with the same arithmetic), and not so long
--- that its square nears overflow (beyond 4 * MAX_LENGTH; up to there Shape:_checkNew
--- decides, on the radius). `fname` names the caller; `what` names the segment (default
--- 'length'; a number i: 'segment i').
---@param fname string
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
---@param what string|integer|nil
function Edge._checkLength(fname, x1, y1, x2, y2, what)
  local dx, dy = (x2 + 0.0) - x1, (y2 + 0.0) - y1 -- (floats: integer differences wrap on Lua 5.3+)
  local len = limits.length(dx, dy)
  if dx - dx ~= 0 or dy - dy ~= 0 then len = huge end -- (the difference overflows)
  if len >= MIN_LENGTH and len <= 4 * MAX_LENGTH then return end
  -- (the name is written only for the error)
  if type(what) == 'number' then what = ('segment %d'):format(what) end
  what = what or 'length'
  if len < MIN_LENGTH then
    fail(('%s: too small: its %s is %s, below %s, the smallest length strike accepts (its square must stay a'
      .. ' normal double)'):format(fname, what, describe(len), describe(MIN_LENGTH)))
  end
  if len > 4 * MAX_LENGTH then
    fail(('%s: too large: its %s is %s, above %s (half of it must be at most %s, the largest length strike'
      .. ' accepts)'):format(fname, what, describe(len), describe(2 * MAX_LENGTH), describe(MAX_LENGTH)))
  end
end
local checkLength = Edge._checkLength

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
  x1, y1, x2, y2 = x1 + 0.0, y1 + 0.0, x2 + 0.0, y2 + 0.0 -- (floats: integer arithmetic wraps on Lua 5.3+)
  local cx, cy = x1 * 0.5 + x2 * 0.5, y1 * 0.5 + y2 * 0.5
  checkLength('strike.Edge', x1, y1, x2, y2)
  self:_setVertices({ x1, x2 }, { y1, y2 }, 2, cx, cy, 0)
  self:_checkNew('strike.Edge')
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
