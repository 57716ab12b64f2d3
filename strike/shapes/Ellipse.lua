--- An ellipse, approximated by an inscribed polygon.
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local ConvexPolygon = require(ROOT .. '.shapes.ConvexPolygon')
local VertexShape = require(ROOT .. '.base.VertexShape')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local ANGLE, SCALE = layout.ANGLE, layout.SCALE
local badSelf, type = check.badSelf, type

local sin, cos, pi, floor, max, min = math.sin, math.cos, math.pi, math.floor, math.max, math.min
local xs, ys = {}, {} -- (the vertices, for the constructor: never kept)

-- The largest ratio of the semi-axes for which the constructor takes its points as they are,
-- without the hull (ConvexPolygon._safeConvex's range, too): the turn at each corner is then
-- at least sin(2 pi / 64) / 16, about 0.006, against the hull's tolerance of 1e-10.
local SAFE_RATIO = 16

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
  local lo, hi = min(a, b), max(a, b)
  -- (edges at least 2 lo sin(pi / n) long, the image of a regular polygon's; and a turn at
  -- every corner far above the hull's tolerance when the semi-axes are within SAFE_RATIO)
  if hi <= SAFE_RATIO * lo and ConvexPolygon._safeConvex(x, y, n, 2 * lo * sin(pi / n), hi) then
    -- (in positive winding from the first point: the hull would return them as they are)
    for k = 1, n do
      local t = 2 * pi * (k - 1) / n
      xs[k], ys[k] = x + a * cos(t) + 0.0, y + b * sin(t) + 0.0
    end
    self:_fromConvex(xs, ys, n, 'strike.Ellipse', a, b, n) -- (its sizes: unpack's)
  else
    local pts = {}
    for k = 1, n do
      local t = 2 * pi * (k - 1) / n
      pts[2 * k - 1], pts[2 * k] = x + a * cos(t), y + b * sin(t)
    end
    VertexShape._sizesNext(a, b, n) -- (its sizes: unpack's)
    Ellipse.super.new(self, pts)
  end
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
