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
---
--- Motion (S.weep, Space:cast, Space:move). A move stops half a skin short of what it meets,
--- the skin a millionth of the moving body's size (space/motion.lua), and that gap must
--- outweigh the rounding of every coordinate the move works with, or the body ends inside what
--- it met (at 1e11 a double is 1.5e-5 apart from the next). So motion has a range, relative to
--- the *size* of the body that moves (its radius; for a body of radius 0, a point, the length
--- of its move): all of it within REACH = 1e7 sizes of the origin, its centroid within
--- REACH - 1 along each axis, at the start and at the end of the move. There the rounding of a
--- coordinate is at most 1e7 * 2^-53 = 1.1e-9 sizes, and the tolerance of the sweeps (ROUND
--- times the largest coordinate of the box the body sweeps, kernels.lua) at most 3.6e-8 sizes:
--- half the skin, 5e-7, is 14 times that. The other bodies are not limited: a sweep's
--- precision is that of the moving body's neighbourhood (a tiny body against a huge one,
--- kernels.lua). checkReach raises the error for a move outside the range, at the caller's line.
local limits = {}

local check = require(((...):gsub('limits$', 'check')))
local abs, sqrt, huge, max = math.abs, math.sqrt, math.huge, math.max

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

--- Motion reaches at most this many sizes of the moving body from the origin (see the
--- header): its centroid stays within REACH - 1 sizes of the origin along each axis, at the
--- start and at the end of the move, so that all of it stays within REACH.
limits.REACH = 1e7
--- REACH - 1, exactly: how many sizes the centroid may be from the origin along an axis.
limits.CENTROID_REACH = limits.REACH - 1
--- The rounding of a quantity computed from coordinates of magnitude m is within ROUND * m
--- (2^-48: 32 units in the last place, a few roundings of a dot product with room to spare).
limits.ROUND = 2 ^ -48

--- The range of motion (see the header) for a body of radius `radius` whose centroid moves
--- from (x0, y0) to (x1, y1): returns its size (the radius; for a body of radius 0 the length
--- of the move, and a point that does not move has size 0 and is no motion), or raises the
--- error for `fname` at the caller's line when a coordinate of the centroid, at the start or
--- at the end, is more than CENTROID_REACH sizes from the origin. (The callers test the common
--- case inline, the same comparisons with the radius, and call this when it fails.)
---@param fname string
---@param radius number
---@param x0 number
---@param y0 number
---@param x1 number
---@param y1 number
---@return number size
function limits.checkReach(fname, radius, x0, y0, x1, y1)
  local size = radius > 0 and radius or limits.length(x1 - x0, y1 - y0)
  local lim = limits.CENTROID_REACH * size
  if x0 <= lim and -x0 <= lim and y0 <= lim and -y0 <= lim and x1 <= lim and -x1 <= lim and y1 <= lim
    and -y1 <= lim or size == 0 then
    return size
  end
  check.fail(('%s: out of the range of motion: the centroid would be %.17g from the origin along an axis, more'
    .. ' than %.17g (limits.REACH - 1) times the size of the body that moves (%s, %.17g): the skin of a move,'
    .. ' a millionth of that size, must outweigh the rounding of its coordinates'):format(fname,
      max(x0, -x0, y0, -y0, x1, -x1, y1, -y1), limits.CENTROID_REACH,
      radius > 0 and 'its radius' or 'it has no radius: the length of its move', size))
end

return limits
