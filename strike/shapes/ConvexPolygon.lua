--- A convex polygon from any number of points, in any order and winding.
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local VertexShape = require(ROOT .. '.base.VertexShape')
local check = require(ROOT .. '.check')
local hull = require(ROOT .. '.geometry.hull')
local vec = require(ROOT .. '.vec')
local unpack = require(ROOT .. '.compat').unpack

local finite, describe, fail = check.finite, check.describe, check.fail

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
  local fname = 'strike.' .. (self.name or 'ConvexPolygon')
  local args, count = ..., select('#', ...)
  if type(args) == 'table' then
    count = #args
  else
    args = { ... }
  end
  if count % 2 ~= 0 then
    fail(('%s: expected x, y pairs, got an odd number of values (%d)'):format(fname, count))
  end
  local xs, ys, n = {}, {}, count / 2
  for i = 1, n do
    local x, y = args[2 * i - 1], args[2 * i]
    if not finite(x) then
      fail(('%s: x%d must be a finite number, got %s'):format(fname, i, describe(x)))
    end
    if not finite(y) then
      fail(('%s: y%d must be a finite number, got %s'):format(fname, i, describe(y)))
    end
    xs[i], ys[i] = x, y
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
  local area, cx, cy = vec.polygonAreaCentroid(hx, hy, h)
  if not (finite(area) and finite(cx) and finite(cy)) or area <= 0 then
    fail(('%s: coordinates too large or too close together (area %s)'):format(fname, describe(area)))
  end
  self:_setVertices(hx, hy, h, cx, cy, area)
end

--- Arguments that rebuild the polygon as it is now: its world vertices x1, y1, x2, y2, ...
---@return number ...
function ConvexPolygon:unpack()
  local v = self:getVertices()
  return unpack(v, 1, 2 * self._n)
end

return ConvexPolygon
