--- A regular polygon inscribed in a circle.
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local ConvexPolygon = require(ROOT .. '.shapes.ConvexPolygon')
local VertexShape = require(ROOT .. '.base.VertexShape')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local ANGLE, SCALE = layout.ANGLE, layout.SCALE
local badSelf, type = check.badSelf, type

local sin, cos, pi = math.sin, math.cos, math.pi
local xs, ys = {}, {} -- (the vertices, for the constructor: never kept)

-- The directions of an n-gon's vertices, sin and cos of a = -2 pi i / n for i = 1..n (flat:
-- sin at 2i - 1, cos at 2i), by n: the very numbers the constructor's formula gives, worked
-- out once for each n its fast path meets (n <= 64: ConvexPolygon._safeConvex).
local directions = {}
local function directionsOf(n)
  local d = directions[n]
  if not d then
    d = {}
    for i = 1, n do
      local a = -2 * pi * i / n
      d[2 * i - 1], d[2 * i] = sin(a), cos(a)
    end
    directions[n] = d
  end
  return d
end

---@class strike.RegularPolygon : strike.ConvexPolygon
local RegularPolygon = ConvexPolygon:extend()
RegularPolygon.name = 'RegularPolygon'

--- The empty instance `RegularPolygon(x, y, n, ...)` fills: room for n vertices.
---@param _ any
---@param _ any
---@param n any
---@return table
function RegularPolygon._alloc(_, _, n) return VertexShape._alloc(n) end

--- An n-sided regular polygon (3 <= n <= 4096) centred on (x, y) with circumradius
--- `radius`, turned by `angle`. Unrotated, vertex n sits at (x, y + radius), as in the
--- original Strike (so n = 4 gives a diamond).
---@param x number
---@param y number
---@param n integer
---@param radius number
---@param angle number|nil
function RegularPolygon:new(x, y, n, radius, angle)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.RegularPolygon:new') end
  check.number(x, 'strike.RegularPolygon', 'x')
  check.number(y, 'strike.RegularPolygon', 'y')
  check.integer(n, 'strike.RegularPolygon', 'side count', 3, 4096)
  check.positive(radius, 'strike.RegularPolygon', 'radius')
  angle = check.optNumber(angle, 'strike.RegularPolygon', 'angle', 0)
  -- (edges 2 radius sin(pi / n) long, at least 0.098 radius for n <= 64)
  if ConvexPolygon._safeConvex(x, y, n, 0.098 * radius, radius) then
    -- (in positive winding from vertex 1: the hull would return them as they are)
    local d = directionsOf(n)
    for i = 1, n do xs[i], ys[i] = x + radius * d[2 * i - 1] + 0.0, y + radius * d[2 * i] + 0.0 end
    self:_fromConvex(xs, ys, n, 'strike.RegularPolygon', n, radius) -- (its sizes: unpack's)
  else
    local pts = {}
    for i = 1, n do
      local a = -2 * pi * i / n
      pts[2 * i - 1], pts[2 * i] = x + radius * sin(a), y + radius * cos(a)
    end
    VertexShape._sizesNext(n, radius)
    RegularPolygon.super.new(self, pts)
  end
  self:_placeCentroid(x, y) -- the exact centre
  if angle ~= 0 then self:rotate(angle) end
end

--- Arguments that rebuild it as it is now: x, y, n, radius, angle.
---@return number, number, integer, number, number
function RegularPolygon:unpack()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:unpack') end
  local cx, cy = self:getCentroid()
  local n, radius = self:_sizes()
  return cx, cy, n, radius * self[SCALE], self[ANGLE]
end

return RegularPolygon
