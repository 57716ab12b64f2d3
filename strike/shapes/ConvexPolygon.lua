--- A convex polygon from any number of points, in any order and winding.
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local VertexShape = require(ROOT .. '.base.VertexShape')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local COUNT, DIRTY, ROUND, SCALE = layout.COUNT, layout.DIRTY, layout.ROUND, layout.SCALE
local limits = require(ROOT .. '.limits')
local hull = require(ROOT .. '.geometry.hull')
local polygon = require(ROOT .. '.geometry.polygon')
local unpack = require(ROOT .. '.compat').unpack
local maxSeparation = require(ROOT .. '.collide.sat').maxSeparation

local abs, max = math.abs, math.max

local finite, describe, fail = check.finite, check.describe, check.fail
local badSelf, type = check.badSelf, type
local MIN_LENGTH, MAX_LENGTH = limits.MIN_LENGTH, limits.MAX_LENGTH

---@class strike.ConvexPolygon : strike.VertexShape
local ConvexPolygon = VertexShape:extend()
ConvexPolygon.name = 'ConvexPolygon'

--- The empty instance `ConvexPolygon(...)` fills: room for as many vertices as points given.
---@param ... any
---@return table
function ConvexPolygon._alloc(...)
  local first = ...
  if type(first) == 'table' then return VertexShape._alloc(math.floor(#first / 2)) end
  return VertexShape._alloc(math.floor(select('#', ...) / 2))
end

--- Build from the points x1, y1, x2, y2, ... (or one table {x1, y1, ...}). The points may
--- come in any order and winding; duplicate and collinear points are dropped. The stored
--- winding is positive (positive shoelace area: counter-clockwise with y up, clockwise on
--- a LÖVE screen), starting from the first point given.
--- Errors: fewer than 3 distinct non-collinear points, a concave outline (use
--- S.trikers.Concave), values that are not finite numbers, or a size outside strike's
--- limits (strike/limits.lua: edges at least 1e-100, radius at most 1e100).
--- Rounded: a table with a `radius` field, {x1, y1, ..., radius = r} (r > 0), gives every
--- point within r of that polygon (it grows by r; its vertices stay the polygon's, its
--- kind is 'rounded').
---@param ... number|number[]
function ConvexPolygon:new(...)
  -- (a subclass's sizes for its local geometry, said just before this call: VertexShape._sizesNext)
  local size1, size2, size3 = VertexShape._takeSizes()
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.ConvexPolygon:new') end
  local fname = self._fname or 'strike.' .. (getmetatable(self).name or 'ConvexPolygon') -- (_fname: see Concave.lua)
  local xs, ys, n = check.coordinates(fname, ...)
  local first = ...
  local rounding = type(first) == 'table' and first.radius or nil
  if rounding ~= nil then ConvexPolygon._checkRounding(fname, rounding) end
  for i = 1, n do xs[i], ys[i] = xs[i] + 0.0, ys[i] + 0.0 end -- (floats: integer products wrap on Lua 5.3+)
  local x0, y0, x1, y1 = math.huge, math.huge, -math.huge, -math.huge
  for i = 1, n do
    local x, y = xs[i], ys[i]
    if x < x0 then x0 = x end
    if x > x1 then x1 = x end
    if y < y0 then y0 = y end
    if y > y1 then y1 = y end
  end
  -- The extent guards the arithmetic of the hull, the area and the centroid (squares and
  -- cubes of it); Shape:_checkNew then applies strike's limits exactly (limits.lua). A
  -- polygon whose extent is out of [MIN_LENGTH / 2, 4 * MAX_LENGTH] is out of them anyway
  -- (its shortest edge is at most 1.5 extents; its radius at least half an extent).
  local extent = max(x1 - x0, y1 - y0)
  if n > 0 and not (extent <= 4 * MAX_LENGTH) then -- luacheck: ignore 581 (inf - inf is NaN)
    fail(('%s: too large: its extent is %s, above %s (its radius must be at most %s, the largest length strike'
      .. ' accepts)'):format(fname, describe(extent), describe(4 * MAX_LENGTH), describe(MAX_LENGTH)))
  end
  if n > 0 and extent > 0 and extent < MIN_LENGTH / 2 then
    fail(('%s: too small: its extent is %s, below %s (its edges must be at least %s, the smallest length strike'
      .. ' accepts)'):format(fname, describe(extent), describe(MIN_LENGTH / 2), describe(MIN_LENGTH)))
  end
  local hx, hy, h, distinct = hull.build(xs, ys, n)
  if h < 3 then
    fail(('%s: needs at least 3 distinct non-collinear points, got %d distinct point%s%s'):format(
      fname, distinct, distinct == 1 and '' or 's', distinct >= 3 and ', all collinear' or ''))
  end
  -- A point equal to a hull vertex is never strictly inside: hull.strictlyInside's first test on
  -- that vertex's own outgoing edge is exactly 0 (a difference times 0, minus one times 0). So
  -- only the other points take the test, which costs up to h steps each: for the points of a
  -- large convex outline (a piece of S.trikers.Concave can have thousands of vertices) it made
  -- this check quadratic. The points usually come in hull order, either winding: a cursor on
  -- the hull, started at the first point and moved one step either way, finds them; a point
  -- it does not find (a dropped collinear one, or points in another order) takes the test, as
  -- before, so the answer and the point an error names are unchanged.
  local cur = 1
  for j = 1, h do
    if hx[j] == xs[1] and hy[j] == ys[1] then
      cur = j
      break
    end
  end
  for i = 1, n do
    local x, y, vertex = xs[i], ys[i], false
    if hx[cur] == x and hy[cur] == y then
      vertex = true
    else
      local nx, pv = cur < h and cur + 1 or 1, cur > 1 and cur - 1 or h
      if hx[nx] == x and hy[nx] == y then
        cur, vertex = nx, true
      elseif hx[pv] == x and hy[pv] == y then
        cur, vertex = pv, true
      end
    end
    if not vertex and hull.strictlyInside(hx, hy, h, x, y) then
      fail(('%s: the points describe a concave polygon (point %d, at %s, %s, is inside the hull);'
        .. ' use S.trikers.Concave for concave outlines'):format(fname, i, describe(xs[i]), describe(ys[i])))
    end
  end
  hull.startAt(hx, hy, h, xs[1], ys[1])
  local area, cx, cy = polygon.areaCentroid(hx, hy, h)
  if not (finite(area) and finite(cx) and finite(cy)) or area <= 0 then
    fail(('%s: coordinates too large or too close together (area %s)'):format(fname, describe(area)))
  end
  if rounding then area, cx, cy = polygon.rounded(hx, hy, h, area, cx, cy, rounding) end
  self:_setVertices(hx, hy, h, cx, cy, area, size1, size2, size3)
  if rounding then self:_setRounding(rounding) end
  self:_checkNew(fname)
end

-- The largest vertex count, and the range of sizes, for which a constructor that knows its
-- points form a convex polygon (Rectangle, RegularPolygon) may skip the hull (see below).
local SAFE_COUNT, SAFE_SMALL, SAFE_LARGE, SAFE_RELATIVE = 64, 1e-80, 1e80, 1e-6

--- Whether a polygon of `n` vertices about (x, y) whose every edge is at least `short` long
--- and which reaches at most `size` from (x, y) may be built by ConvexPolygon._fromConvex:
--- few vertices, sizes far inside strike's limits (limits.lua), and edges far longer than
--- the rounding of coordinates near (x, y), so that its points stay distinct and convex
--- once rounded. Outside this, the constructor takes the general path, with its errors.
---@param x number
---@param y number
---@param n integer
---@param short number
---@param size number
---@return boolean
function ConvexPolygon._safeConvex(x, y, n, short, size)
  return n <= SAFE_COUNT and short >= SAFE_SMALL and size <= SAFE_LARGE
    and short >= SAFE_RELATIVE * (abs(x) + abs(y))
end

--- Build from points known to form a strictly convex polygon, distinct, in positive winding
--- and starting from the first point given (floats, count n, in ConvexPolygon._safeConvex's
--- range): what ConvexPolygon:new does, without the hull that checks and orders them (on such
--- points the hull returns them as they are). The result is the same to the bit. `size1` ...
--- are the class's sizes (VertexShape.lua's header), nil for none.
---@param xs number[]
---@param ys number[]
---@param n integer
---@param fname string
---@param size1 number|nil
---@param size2 number|nil
---@param size3 number|nil
function ConvexPolygon:_fromConvex(xs, ys, n, fname, size1, size2, size3)
  local area, cx, cy = polygon.areaCentroid(xs, ys, n)
  self:_setVertices(xs, ys, n, cx, cy, area, size1, size2, size3)
  self:_checkNew(fname)
end

--- Raise an error at the caller's line unless r is a rounding radius strike accepts: a
--- number from MIN_LENGTH to MAX_LENGTH (limits.lua). `fname` names the constructor.
---@param fname string
---@param r any
function ConvexPolygon._checkRounding(fname, r)
  check.positive(r, fname, 'radius')
  if r < MIN_LENGTH or r > MAX_LENGTH then
    fail(('%s: radius out of range: got %s, strike accepts lengths from %s to %s'):format(fname, describe(r),
      describe(MIN_LENGTH), describe(MAX_LENGTH)))
  end
end

-- The faces of the given shapes that are seams (`_seams`, see strike/base/VertexShape.lua),
-- as VertexShape:_seamsFrom reads them: x1, y1, x2, y2, seam per face; and their count.
local function seamFaces(a, b)
  local src, count = {}, 0
  for _, s in ipairs({ a, b }) do
    local seams = s._seams
    if seams then
      for i = 1, s[COUNT] do
        if seams[i] then
          local k = 5 * count
          src[k + 1], src[k + 2], src[k + 3], src[k + 4] = s:getEdge(i)
          src[k + 5] = seams[i]
          count = count + 1
        end
      end
    end
  end
  return src, count
end

--- The union of this polygon and `other` as a new ConvexPolygon when that union is convex
--- (the two touch without overlapping and fill their common hull) and within strike's limits
--- on lengths, else false.
--- Test: interiors disjoint (some face separates them, within a relative 1e-9) and
--- area(hull of both) = area(self) + area(other) (relative 1e-9).
--- Seams (pieces of a compound, `_seams`): a face of the union is a seam where it runs along
--- a seam face of either polygon; the face they shared is inside the union and gone.
---@param other strike.Shape
---@return strike.ConvexPolygon|false
function ConvexPolygon:merge(other)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.ConvexPolygon:merge') end
  if type(other) ~= 'table' or other._kind ~= 'polygon' or not other[COUNT] or other[COUNT] < 3 then return false end
  if self._kind ~= 'polygon' then return false end -- (a rounded polygon's union is never a polygon)
  if self[DIRTY] then self:_refresh() end
  if other[DIRTY] then other:_refresh() end
  local tol = 1e-9 * max(self:getRadius(), other:getRadius())
  if max(maxSeparation(self, other), maxSeparation(other, self)) < -tol then return false end
  local xs, ys, n = {}, {}, 0
  for _, s in ipairs({ self, other }) do
    for i = 1, s[COUNT] do
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
  -- (the union may be outside strike's limits on lengths, limits.lua: then it is no merge)
  local ok, merged = pcall(ConvexPolygon, pts)
  if ok and (self._seams or other._seams) then
    local src, count = seamFaces(self, other)
    if count > 0 then merged._seams = merged:_seamsFrom(src, count) end
  end
  return ok and merged
end

--- Arguments that rebuild the polygon as it is now: its world vertices x1, y1, x2, y2, ...;
--- for a rounded polygon, one table of them with its radius, {x1, y1, ..., radius = r} (the
--- table form of the constructor).
---@return number|table ...
function ConvexPolygon:unpack()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:unpack') end
  local v = self:getVertices()
  if self[ROUND] > 0 then
    v.radius = self[ROUND] * self[SCALE]
    return v
  end
  return unpack(v, 1, 2 * self[COUNT])
end

return ConvexPolygon
