--- The sizes strike accepts, and unit vectors that stay unit at any size.
---
--- Lengths. Every length of a shape, in every pose, lies in [MIN_LENGTH, MAX_LENGTH] =
--- [1e-100, 1e100]: its shortest length (a polygon's or an edge's shortest edge, a circle's
--- radius; a point has none) at least MIN_LENGTH, its radius (from the centroid to the
--- farthest point) at most MAX_LENGTH. Constructors refuse shapes outside that range, and a
--- transform (a shape's or a collider's scale) refuses to take a shape out of it, with the
--- same test (sizeError in base/Shape.lua, run by Shape:_checkNew and Shape._checkPose), so
--- that what a constructor refuses a transform refuses too.
--- Why these numbers: the arithmetic that builds a shape squares lengths (edge normals,
--- areas, the hull's turn test) and multiplies areas by lengths (the area-weighted
--- centroid), so it needs lengths, squares and cubes to be normal doubles with full
--- precision: 2.2e-308 to 1.8e308. A squared length below that is subnormal or 0 (an Edge
--- 1e-200 long had a NaN normal; at 1e-160 its normal had length 1.0000056); above, it is
--- infinite. [1e-100, 1e100] keeps cubes within [1e-300, 1e300], with room to spare for
--- sums and constant factors.
---
--- Coordinates. Any finite coordinate is accepted as long as |x| + |y| + radius stays finite
--- for the shape's centroid (x, y) (so that projections on a unit vector cannot overflow),
--- by constructors and by every transform (translate, rotate, scale) alike.
---
--- Run time. Distances between shapes are not bounded by any of this: two points may be
--- 1e-200 apart, two circles 1e308. Normals computed at run time from such a distance use
--- `direction` below when its square is not a normal double in [TINY2, huge) (one
--- comparison more on the common path). Rays from far away: see collide/ray.lua.
local limits = {}

local abs, sqrt, huge = math.abs, math.sqrt, math.huge

--- The smallest length a shape may have (see the header): its square, 1e-200, and cube,
--- 1e-300, are normal doubles.
limits.MIN_LENGTH = 1e-100
--- The largest length a shape may have: its square and cube stay far from overflow.
limits.MAX_LENGTH = 1e100
--- Squared distances at or above this (and finite) give a unit vector by the plain
--- sqrt(dx * dx + dy * dy), within a few rounding errors: a square this size is normal with
--- eight orders of magnitude to spare, so a subnormal or underflowed term of the sum is
--- lost in its rounding. Below it, or infinite, use `unit`.
limits.TINY2 = 1e-300

--- The unit vector along (dx, dy) and its length, for any finite (dx, dy) but (0, 0):
--- scaled by the larger component first, so that neither underflow nor overflow spoils it
--- (the length may be math.huge when it exceeds the largest double). nil for (0, 0).
---@param dx number
---@param dy number
---@return number|nil ux
---@return number uy
---@return number length
function limits.unit(dx, dy)
  dx, dy = dx + 0.0, dy + 0.0 -- (floats: integer products wrap around on Lua 5.3+)
  local m, ay = abs(dx), abs(dy)
  if ay > m then m = ay end
  if not (m > 0) then return nil end -- luacheck: ignore 581 ((0, 0))
  local x, y = dx / m, dy / m
  local l = sqrt(x * x + y * y)
  return x / l, y / l, m * l
end

--- The length of (dx, dy) for any finite components, without underflow or overflow on the
--- way (math.huge when it exceeds the largest double).
---@param dx number
---@param dy number
---@return number
function limits.length(dx, dy)
  dx, dy = dx + 0.0, dy + 0.0 -- (floats: integer products wrap around on Lua 5.3+)
  local d2 = dx * dx + dy * dy
  if d2 >= limits.TINY2 and d2 < huge then return sqrt(d2) end
  local _, _, l = limits.unit(dx, dy)
  return l or 0
end

--- The unit vector from (ax, ay) toward (bx, by) and the distance between them, for any
--- finite coordinates, even when their difference overflows (the distance is then
--- math.huge); nil when the points are equal. The slow path of the run-time normals
--- (collide/sat.lua).
---@param ax number
---@param ay number
---@param bx number
---@param by number
---@return number|nil ux
---@return number uy
---@return number distance
function limits.direction(ax, ay, bx, by)
  local dx, dy = (bx + 0.0) - ax, (by + 0.0) - ay
  if dx - dx == 0 and dy - dy == 0 then return limits.unit(dx, dy) end
  local ux, uy, l = limits.unit(bx * 0.5 - ax * 0.5, by * 0.5 - ay * 0.5) -- (halved: no overflow)
  return ux, uy, 2 * l
end

return limits
