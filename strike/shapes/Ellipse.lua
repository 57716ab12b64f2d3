--- An ellipse, approximated by an inscribed polygon.
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local ConvexPolygon = require(ROOT .. '.shapes.ConvexPolygon')
local VertexShape = require(ROOT .. '.base.VertexShape')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local ANGLE, SCALE = layout.ANGLE, layout.SCALE
local badSelf, type = check.badSelf, type

local sin, cos, pi, floor, max, min = math.sin, math.cos, math.pi, math.floor, math.max, math.min

---@class strike.Ellipse : strike.ConvexPolygon
local Ellipse = ConvexPolygon:extend()
Ellipse.name = 'Ellipse'

--- An ellipse centred on (x, y) with semi-axes a (along x) and b (along y), approximated by
--- an inscribed polygon of n segments (3 <= n <= 4096; default max(8, 4 * floor(a / b)),
--- at most 64), turned by `angle`.
---@param x number
---@param y number
---@param a number
---@param b number
---@param n integer|nil
---@param angle number|nil
function Ellipse:new(x, y, a, b, n, angle)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Ellipse:new') end
  check.number(x, 'strike.Ellipse', 'x')
  check.number(y, 'strike.Ellipse', 'y')
  check.positive(a, 'strike.Ellipse', 'semi-axis a')
  check.positive(b, 'strike.Ellipse', 'semi-axis b')
  if n == nil then
    n = min(64, max(8, 4 * floor(a / b)))
  else
    check.integer(n, 'strike.Ellipse', 'segment count', 3, 4096)
  end
  angle = check.optNumber(angle, 'strike.Ellipse', 'angle', 0)
  local pts = {}
  for k = 1, n do
    local t = 2 * pi * (k - 1) / n
    pts[2 * k - 1], pts[2 * k] = x + a * cos(t), y + b * sin(t)
  end
  VertexShape._sizesNext(a, b, n) -- (its sizes: unpack's)
  Ellipse.super.new(self, pts)
  self:_placeCentroid(x, y) -- the exact centre
  if angle ~= 0 then self:rotate(angle) end
end

--- Arguments that rebuild it as it is now: x, y, a, b, n, angle.
---@return number, number, number, number, integer, number
function Ellipse:unpack()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:unpack') end
  local s = self[SCALE]
  local cx, cy = self:getCentroid()
  local a, b, n = self:_sizes()
  return cx, cy, a * s, b * s, n, self[ANGLE]
end

return Ellipse
