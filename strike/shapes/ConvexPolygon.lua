--- A convex polygon from any number of points, in any order and winding.
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local VertexShape = require(ROOT .. '.base.VertexShape')
local check = require(ROOT .. '.check')
local hull = require(ROOT .. '.geometry.hull')
local polygon = require(ROOT .. '.geometry.polygon')
local unpack = require(ROOT .. '.compat').unpack
local maxSeparation = require(ROOT .. '.collide.sat').maxSeparation

local abs, max = math.abs, math.max

local finite, describe, fail = check.finite, check.describe, check.fail
local badSelf, type = check.badSelf, type

---@class strike.ConvexPolygon : strike.VertexShape
local ConvexPolygon = VertexShape:extend()
ConvexPolygon.name = 'ConvexPolygon'

--- Build from the points x1, y1, x2, y2, ... (or one table {x1, y1, ...}). The points may
--- come in any order and winding; duplicate and collinear points are dropped. The stored
--- winding is positive (positive shoelace area: counter-clockwise with y up, clockwise on
--- a LÖVE screen), starting from the first point given.
--- Errors: fewer than 3 distinct non-collinear points, a concave outline (use
--- S.trikers.Concave), or values that are not finite numbers.
---@param ... number|number[]
function ConvexPolygon:new(...)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.ConvexPolygon:new') end
  local fname = 'strike.' .. (self.name or 'ConvexPolygon')
  local xs, ys, n = check.coordinates(fname, ...)
  local x0, y0, x1, y1 = math.huge, math.huge, -math.huge, -math.huge
  for i = 1, n do
    local x, y = xs[i], ys[i]
    if x < x0 then x0 = x end
    if x > x1 then x1 = x end
    if y < y0 then y0 = y end
    if y > y1 then y1 = y end
  end
  local d2 = (x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0)
  if n > 0 and not finite(d2 * d2) then -- the hull's turn test multiplies squared lengths
    fail(('%s: coordinates too large (their extent overflows)'):format(fname))
  end
  local hx, hy, h, distinct = hull.build(xs, ys, n)
  if h < 3 then
    fail(('%s: needs at least 3 distinct non-collinear points, got %d distinct point%s%s'):format(
      fname, distinct, distinct == 1 and '' or 's', distinct >= 3 and ', all collinear' or ''))
  end
  for i = 1, n do
    if hull.strictlyInside(hx, hy, h, xs[i], ys[i]) then
      fail(('%s: the points describe a concave polygon (point %d, at %s, %s, is inside the hull);'
        .. ' use S.trikers.Concave for concave outlines'):format(fname, i, describe(xs[i]), describe(ys[i])))
    end
  end
  hull.startAt(hx, hy, h, xs[1], ys[1])
  local area, cx, cy = polygon.areaCentroid(hx, hy, h)
  if not (finite(area) and finite(cx) and finite(cy)) or area <= 0 then
    fail(('%s: coordinates too large or too close together (area %s)'):format(fname, describe(area)))
  end
  self:_setVertices(hx, hy, h, cx, cy, area)
end

--- The union of this polygon and `other` as a new ConvexPolygon when that union is convex
--- (the two touch without overlapping and fill their common hull), else false.
--- Test: interiors disjoint (some face separates them, within a relative 1e-9) and
--- area(hull of both) = area(self) + area(other) (relative 1e-9).
---@param other strike.Shape
---@return strike.ConvexPolygon|false
function ConvexPolygon:merge(other)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.ConvexPolygon:merge') end
  if type(other) ~= 'table' or other.kind ~= 'polygon' or not other._n or other._n < 3 then return false end
  if self._dirty then self:_refresh() end
  if other._dirty then other:_refresh() end
  local tol = 1e-9 * max(self:getRadius(), other:getRadius())
  if max(maxSeparation(self, other), maxSeparation(other, self)) < -tol then return false end
  local xs, ys, n = {}, {}, 0
  for _, s in ipairs({ self, other }) do
    for i = 1, s._n do
      n = n + 1
      xs[n], ys[n] = s:getVertex(i)
    end
  end
  local hx, hy, h = hull.build(xs, ys, n)
  local area = polygon.areaCentroid(hx, hy, h)
  local sum = self:getArea() + other:getArea()
  if abs(area - sum) > 1e-9 * sum then return false end
  local pts = {}
  for i = 1, h do pts[2 * i - 1], pts[2 * i] = hx[i], hy[i] end
  return ConvexPolygon(pts)
end

--- Arguments that rebuild the polygon as it is now: its world vertices x1, y1, x2, y2, ...
---@return number ...
function ConvexPolygon:unpack()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:unpack') end
  local v = self:getVertices()
  return unpack(v, 1, 2 * self._n)
end

return ConvexPolygon
