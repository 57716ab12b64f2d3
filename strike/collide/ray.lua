--- Ray queries: pure functions on shapes (and on leaf lists of colliders). The shape
--- methods rayIntersections, rayIntersects, rayCast and segmentCast validate their
--- arguments and call these.
---
--- A ray is an origin (ox, oy) and a direction, normalised here: every distance t is
--- measured along the unit direction (ux, uy), and only t >= 0 counts (nothing behind the
--- origin). The points of a ray inside a closed convex shape form one interval [lo, hi] of
--- t; the ray's hits are its ends clipped to t >= 0:
---   lo >= 0, lo < hi   two hits, lo then hi (a ray starting on the boundary and entering
---                      has lo = 0);
---   lo >= 0, lo == hi  one hit (a graze at a vertex or a tangent);
---   lo < 0 <= hi       one hit, hi: the ray starts inside and only its exit is reported
---                      (a ray starting on the boundary and leaving reports just 0);
---   hi < 0, or empty   no hit.
---
--- Polygons: parametric clipping against the face half-planes, M. Cyrus and J. Beck,
--- "Generalized two- and three-dimensional clipping", Computers & Graphics 3(1), 1978.
--- Face i keeps the points p with dot(n_i, p) <= d_i (world normal and offset, cached by
--- the shape); along the ray that is t * dot(n_i, u) <= d_i - dot(n_i, o). A face the
--- ray runs parallel to either keeps the whole ray or none of it, so an edge parallel to
--- the ray needs no special case: the neighbouring faces bound the interval.
--- Segments (Edge): a degenerate polygon, intersected directly: the ray's parameter and
--- the segment's from the two cross products; a collinear ray gives the overlap interval.
--- Circles: C. Ericson, Real-Time Collision Detection (2005), 5.3.2 (intersecting a ray
--- against a sphere), t^2 + 2bt + c = 0 with b = dot(m, u), c = dot(m, m) - r^2 and
--- m = o - centre, solved in the numerically stable form: the discriminant is taken as
--- r^2 - |m - b u|^2 (the squared distance from the centre to the line, which avoids the
--- cancellation in b^2 - c), and the roots as q = -(b + sign(b) sqrt(disc)) and c / q.
---
--- Each kind's kernel (registered in kinds.lua, looked up through dispatch.kind) gives the
--- interval and the outward unit normals at both of its ends; the queries below pick.
---
--- Far origins. A kernel measures from the ray's origin, so its answers have the precision of
--- the origin's distance: from x = -1e300, every face of a unit square is entered at "1e300",
--- and the interval's ends tie or cross at random (such a ray missed a diamond it went
--- through). A ray whose origin is more than FAR (2^20) times the shape's radius from the
--- shape's centroid is therefore first moved along itself to two radii before the point
--- nearest the centroid; the kernel works from there, at the shape's scale, and the
--- distances are the move plus the kernel's. The move is exact for axis-aligned rays; for
--- others it is off by a rounding of the distance, which is the precision the direction
--- itself has that far away (the answer is exact for a direction that differs from the
--- given one by a rounding). Every hit has a unit normal; a hit whose distance would exceed
--- the largest double is not reported (a miss), by every ray query alike.
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local COUNT, DIRTY, RADIUS, SCALE = layout.COUNT, layout.DIRTY, layout.RADIUS, layout.SCALE
local kinds = require(ROOT .. '.collide.dispatch').kind
local badKind = require(ROOT .. '.reserved').badKind
local limits = require(ROOT .. '.limits')

local X, Y, R = layout.X, layout.Y, layout.R
local STRIDE, FIRST, VY, NX, NY, D = layout.STRIDE, layout.FIRST, layout.VY, layout.NX, layout.NY, layout.D
local BASE = layout.BASE
local P1, P2 = layout.base(1), layout.base(2)

local sqrt, abs, huge = math.sqrt, math.abs, math.huge

-- Far origins (see the header): a ray whose origin is more than FAR times the shape's
-- radius from its centroid is moved close to the shape first.
local FAR = 2 ^ 20
local finite, fail, describe, number = check.finite, check.fail, check.describe, check.number

local ray = {}

-- Validation ------------------------------------------------------------------------

--- Raise an error at the caller's line unless x, y, dx, dy are finite numbers and
--- (dx, dy) is not the zero vector. `fname` names the public function.
---@param fname string
---@param x any
---@param y any
---@param dx any
---@param dy any
function ray.checkRay(fname, x, y, dx, dy)
  if not (finite(x) and finite(y) and finite(dx) and finite(dy)) then
    number(x, fname, 'x')
    number(y, fname, 'y')
    number(dx, fname, 'dx')
    number(dy, fname, 'dy')
  end
  if dx == 0 and dy == 0 then fail(fname .. ': the direction must not be zero') end
end

--- Raise an error at the caller's line unless x1, y1, x2, y2 are finite numbers.
---@param fname string
---@param x1 any
---@param y1 any
---@param x2 any
---@param y2 any
function ray.checkSegment(fname, x1, y1, x2, y2)
  if not (finite(x1) and finite(y1) and finite(x2) and finite(y2)) then
    number(x1, fname, 'x1')
    number(y1, fname, 'y1')
    number(x2, fname, 'x2')
    number(y2, fname, 'y2')
  end
end

--- The maximum distance of a cast: nil means math.huge; anything but a number >= 0
--- (math.huge allowed, NaN not) raises an error at the caller's line.
---@param fname string
---@param maxDistance any
---@return number
function ray.checkMax(fname, maxDistance)
  if maxDistance == nil then return huge end
  if type(maxDistance) ~= 'number' or not (maxDistance >= 0) then -- luacheck: ignore 581 (NaN is rejected)
    fail(('%s: maxDistance must be a number >= 0 or nil, got %s'):format(fname, describe(maxDistance)))
  end
  return maxDistance
end

--- Raise an error at the caller's line unless `ts` is a table or nil.
---@param fname string
---@param ts any
function ray.checkTs(fname, ts)
  if ts ~= nil and type(ts) ~= 'table' then
    fail(('%s: ts must be a table or nil, got %s'):format(fname, describe(ts)))
  end
end

-- Geometry ---------------------------------------------------------------------------

-- The unit vector along (dx, dy) and its length, scaled by the larger component first so
-- that neither overflow nor underflow spoils it (limits.unit; a ray's direction is never
-- the zero vector, checkRay refuses it).
local unit = limits.unit

-- The faces of polygonClip's last hit, as the slots where their vertex records start (face
-- i's is layout.base(i)): the entering face (0 when none) and the leaving one. Read by the
-- leaf-list queries for pieces with seams (see the end of this file).
local clipIn, clipOut = 0, 0

--- Cyrus–Beck clipping of the ray (origin (ox, oy), unit direction (ux, uy)) against a
--- convex polygon (3 or more vertices). Returns the interval lo, hi of the whole line
--- inside the polygon (lo may be negative; hi >= 0) and the normals of the faces that
--- bound it: the entering face's at lo, the leaving face's at hi (on ties, the first face
--- in order). Returns nil when the ray misses. Which faces those are is left in clipIn and
--- clipOut.
---@param s strike.VertexShape
---@param ox number
---@param oy number
---@param ux number
---@param uy number
---@return number|nil lo
---@return number hi
---@return number nxLo
---@return number nyLo
---@return number nxHi
---@return number nyHi
local function polygonClip(s, ox, oy, ux, uy)
  if s[DIRTY] then s:_refresh() end
  local tin, tout, fin, fout = -huge, huge, 0, 0
  for k = FIRST, STRIDE * s[COUNT] + BASE, STRIDE do
    local nx, ny = s[k + NX], s[k + NY]
    local den = nx * ux + ny * uy
    local num = s[k + D] - (nx * ox + ny * oy)
    if den < 0 then -- entering: t >= num / den
      local t = num / den
      if t > tin then
        if t > tout then return nil end
        tin, fin = t, k
      end
    elseif den > 0 then -- leaving: t <= num / den
      local t = num / den
      if t < tout then
        if t < tin then return nil end
        tout, fout = t, k
      end
    elseif num < 0 then -- parallel to the face and outside it
      return nil
    end
  end
  -- (behind the origin; the other two tests only fail for coordinates near overflow)
  if not (tout >= 0) or tout == huge or tin == huge then return nil end -- luacheck: ignore 581 (NaN reads as a miss)
  local nxLo, nyLo = 0, 0 -- (a ray starting inside has no entering face; lo < 0 is not reported)
  if fin > 0 then nxLo, nyLo = s[fin + NX], s[fin + NY] end
  clipIn, clipOut = fin, fout
  return tin, tout, nxLo, nyLo, s[fout + NX], s[fout + NY]
end
--- The polygon kernel (above): Cyrus–Beck clipping.
ray.polygon = polygonClip

--- The ray against a segment (an Edge or a chain segment, 2 vertices). Returns lo, hi
--- (lo <= hi, hi >= 0) and the normals there: for a crossing (lo == hi), the side facing
--- the ray's origin; for a collinear ray (lo, hi: the overlap's ends along the ray), the
--- segment's direction at each end (-u at lo, +u at hi). Returns nil when the ray misses.
---@param s strike.VertexShape
---@param ox number
---@param oy number
---@param ux number
---@param uy number
---@return number|nil lo
---@return number hi
---@return number nxLo
---@return number nyLo
---@return number nxHi
---@return number nyHi
local function segmentClip(s, ox, oy, ux, uy)
  if s[DIRTY] then s:_refresh() end
  local ax, ay = s[P1] - ox, s[P1 + VY] - oy -- p1 relative to the origin
  local ex, ey = s[P2] - s[P1], s[P2 + VY] - s[P1 + VY]
  -- o + t u = p1 + s e: t = cross(a, e) / cross(u, e), s = cross(a, u) / cross(u, e).
  -- (e is scaled to components of at most 1, so that cross(a, e) cannot overflow.)
  local k = abs(ex)
  if abs(ey) > k then k = abs(ey) end
  ex, ey = ex / k, ey / k
  local den = ux * ey - uy * ex
  local cau = ax * uy - ay * ux
  if den ~= 0 then
    local sp = cau / (den * k)
    if not (sp >= 0 and sp <= 1) then return nil end
    local t = (ax * ey - ay * ex) / den
    if not (t >= 0) or t == huge then return nil end -- luacheck: ignore 581 (NaN reads as a miss)
    -- (the sign of cross(u, e) is the sign of dot(u, normal 1): the side facing the origin)
    local nx, ny = s[P1 + NX], s[P1 + NY]
    if den > 0 then nx, ny = -nx, -ny end
    return t, t, nx, ny, nx, ny
  end
  if cau ~= 0 then return nil end -- parallel, on another line
  local t1 = ax * ux + ay * uy
  local t2 = (s[P2] - ox) * ux + (s[P2 + VY] - oy) * uy
  if t1 > t2 then t1, t2 = t2, t1 end
  if not (t2 >= 0) or t2 == huge then return nil end -- luacheck: ignore 581 (NaN reads as a miss)
  return t1, t2, -ux, -uy, ux, uy
end
--- The segment kernel (above).
ray.segment = segmentClip

--- The ray against any shape of the 'polygon' kind: polygons, and edges as segments.
---@param s strike.VertexShape
---@param ox number
---@param oy number
---@param ux number
---@param uy number
---@return number|nil lo
---@return number hi
---@return number nxLo
---@return number nyLo
---@return number nxHi
---@return number nyHi
function ray.vertexShape(s, ox, oy, ux, uy)
  if s[COUNT] == 2 then return segmentClip(s, ox, oy, ux, uy) end
  return polygonClip(s, ox, oy, ux, uy)
end

-- The outward unit normal of a circle along (hx, hy), the hit point relative to the centre
-- (limits.unit: scaled before it is squared, so that tiny or huge circles still give a unit
-- vector); -u when there is none (the zero vector: a circle of radius 0, a point, whose
-- normal faces the ray; or a component that overflowed, which makes it NaN).
local function circleNormal(hx, hy, ux, uy)
  local nx, ny = unit(hx, hy)
  if nx and nx == nx then return nx, ny end
  return -ux, -uy
end

--- The ray against a circle: lo, hi (lo <= hi, hi >= 0) and the outward unit normals there,
--- or nil when the ray misses. A circle of radius 0 (a point) is hit only by a ray through
--- it; its normal faces the ray (-u). The hit points relative to the centre are taken as
--- p -+ sqrt(disc) u, with p the centre's nearest point of the line, rather than as
--- o + t u - centre, which cancels when the origin is far away.
---@param s strike.Circle
---@param ox number
---@param oy number
---@param ux number
---@param uy number
---@return number|nil lo
---@return number hi
---@return number nxLo
---@return number nyLo
---@return number nxHi
---@return number nyHi
function ray.circle(s, ox, oy, ux, uy)
  if s[DIRTY] then s:_refresh() end
  local r, cx, cy = s[R], s[X], s[Y]
  local mx, my = ox - cx, oy - cy
  local b = mx * ux + my * uy
  local c = (mx * mx + my * my) - r * r
  if c > 0 and b > 0 then return nil end -- outside and pointing away
  local px, py = mx - b * ux, my - b * uy -- from the centre to the nearest point of the line
  local disc = r * r - (px * px + py * py)
  if not (disc >= 0) then return nil end -- luacheck: ignore 581 (NaN reads as a miss)
  if r == 0 and (px ~= 0 or py ~= 0) then return nil end -- (a point: p * p may have underflowed)
  local t1, t2, root
  if disc == 0 then
    t1, root = -b, 0
    t2 = t1
  else
    root = sqrt(disc)
    local q
    if b >= 0 then q = -(b + root) else q = root - b end
    t1 = q
    if c < huge then
      t2 = c / q
    else -- (|m|^2 overflowed: the origin is so far away that -b -+ sqrt(disc) cannot cancel)
      t2 = -b - (q + b)
    end
    if t1 > t2 then t1, t2 = t2, t1 end
  end
  if not (t2 >= 0) or t2 == huge then return nil end -- luacheck: ignore 581 (NaN reads as a miss)
  local nxLo, nyLo = circleNormal(px - root * ux, py - root * uy, ux, uy)
  local nxHi, nyHi = circleNormal(px + root * ux, py + root * uy, ux, uy)
  return t1, t2, nxLo, nyLo, nxHi, nyHi
end

--- The ray against a rounded shape (collide/rounded.lua: a core and a radius r): its
--- boundary is the core's faces moved out by r (kept where the foot of the point lies on
--- the face) and arcs of the circles of radius r about the core's vertices. Every point of
--- those whole circles is within r of the core, so it lies in the shape: the interval of
--- the line inside the (convex) shape runs from the smallest to the largest parameter at
--- which the line meets any face or any such circle. Returns lo, hi and the outward unit
--- normals there (a face's, or (hit - vertex) / r), or nil when the ray misses.
---@param s strike.VertexShape
---@param ox number
---@param oy number
---@param ux number
---@param uy number
---@return number|nil lo
---@return number hi
---@return number nxLo
---@return number nyLo
---@return number nxHi
---@return number nyHi
function ray.rounded(s, ox, oy, ux, uy)
  if s[DIRTY] then s:_refresh() end
  local r, n = s[R], s[COUNT]
  local lo, hi, nxLo, nyLo, nxHi, nyHi = huge, -huge, 0, 0, 0, 0
  for i = 1, n do
    local k, l = STRIDE * i + BASE, STRIDE * (i < n and i + 1 or 1) + BASE
    local vx, vy = s[k], s[k + VY]
    -- the circle about vertex i: t^2 + 2 b t + c = 0 with m = o - v (see ray.circle)
    local mx, my = ox - vx, oy - vy
    local b = mx * ux + my * uy
    local px, py = mx - b * ux, my - b * uy
    local disc = r * r - (px * px + py * py)
    if disc >= 0 then
      local root = sqrt(disc)
      local t1, t2 = -b - root, -b + root
      if t1 < lo then lo, nxLo, nyLo = t1, (px - root * ux) / r, (py - root * uy) / r end
      if t2 > hi then hi, nxHi, nyHi = t2, (px + root * ux) / r, (py + root * uy) / r end
    end
    -- face i moved out by r, where it is the boundary
    local nx, ny = s[k + NX], s[k + NY]
    local den = nx * ux + ny * uy
    local ex, ey = s[l] - vx, s[l + VY] - vy
    local e2 = ex * ex + ey * ey
    if den ~= 0 and e2 > 0 then
      local t = (s[k + D] + r - (nx * ox + ny * oy)) / den
      local f = (ox + t * ux - vx) * ex + (oy + t * uy - vy) * ey
      if f >= 0 and f <= e2 then
        if t < lo then lo, nxLo, nyLo = t, nx, ny end
        if t > hi then hi, nxHi, nyHi = t, nx, ny end
      end
    end
  end
  if not (hi >= 0) or hi == huge or lo == huge then return nil end -- luacheck: ignore 581 (NaN reads as a miss)
  return lo, hi, nxLo, nyLo, nxHi, nyHi
end

-- Where span's kernel measured from: the point (shiftX, shiftY), at distance shiftT along
-- the ray from its origin (0 and the origin itself unless the origin is far).
local shiftT, shiftX, shiftY = 0, 0, 0
-- shiftT as the unrounded sum shiftFar + shiftNear: the long move, then the short one.
local shiftFar, shiftNear = 0, 0
-- The distance of the last hit ray.cast reported, as the unrounded sum castFar + castNear.
local castFar, castNear = 0, 0

-- The kernel's answer for the ray on shape s, measured from (shiftX, shiftY) (set here).
-- A ray whose origin is more than FAR radii from the shape's centroid is first moved along
-- itself to two radii before the point nearest the centroid (see "Far origins" in the
-- header); nil when it cannot reach the shape, or when the hit's distance would exceed the
-- largest double.
local function span(s, ox, oy, ux, uy)
  local dx, dy = s[X] - ox, s[Y] - oy
  local rad = s[RADIUS] * s[SCALE]
  if not (abs(dx) + abs(dy) > FAR * rad) or rad == 0 then -- luacheck: ignore 581 (inf is far)
    shiftT, shiftX, shiftY, shiftFar, shiftNear = 0, ox, oy, 0, 0
    local kind = kinds[s._kind]
    if not kind then badKind('strike', s) end -- (a `_kind` a game changed)
    return kind.ray(s, ox, oy, ux, uy)
  end
  local t0 = dx * ux + dy * uy -- (far away: no point of the shape is within 2 radii of the origin)
  if not (t0 > 2 * rad) or t0 == huge then return nil end -- luacheck: ignore 581 (behind, or overflowed)
  local px, py = ox + t0 * ux, oy + t0 * uy -- near the centroid, within a rounding of t0
  local t1 = (s[X] - px) * ux + (s[Y] - py) * uy - 2 * rad -- (at the shape's scale: exact enough)
  px, py = px + t1 * ux, py + t1 * uy
  shiftT, shiftX, shiftY, shiftFar, shiftNear = t0 + t1, px, py, t0, t1
  local kind = kinds[s._kind]
  if not kind then badKind('strike', s) end
  return kind.ray(s, px, py, ux, uy)
end

--- The interval lo, hi of the ray inside any shape, and the normals at its ends (see the
--- kinds' kernels above), or nil.
---@param s strike.Shape
---@param ox number
---@param oy number
---@param ux number
---@param uy number
---@return number|nil lo
---@return number hi
---@return number nxLo
---@return number nyLo
---@return number nxHi
---@return number nyHi
function ray.clip(s, ox, oy, ux, uy)
  local lo, hi, nxLo, nyLo, nxHi, nyHi = span(s, ox, oy, ux, uy)
  if lo and shiftT ~= 0 then
    lo, hi = lo + shiftT, hi + shiftT
    if hi == huge then return nil end -- (beyond the largest double)
  end
  return lo, hi, nxLo, nyLo, nxHi, nyHi
end
local clip = ray.clip

-- Fill `ts` (a table, or nil for a new one) with the hits of the ray, unit direction:
-- ts, n; or nil, 0 (and `ts` emptied) when there is none.
local function fill(s, ox, oy, ux, uy, ts)
  local lo, hi = span(s, ox, oy, ux, uy)
  local two = lo and hi ~= lo -- (decided at the shape's scale: far away both may round alike)
  if lo and shiftT ~= 0 then
    lo, hi = lo + shiftT, hi + shiftT
    if hi == huge then lo = nil end -- (beyond the largest double)
  end
  if not lo then
    if ts then
      for i = #ts, 1, -1 do ts[i] = nil end
    end
    return nil, 0
  end
  if hi == 0 then hi = 0.0 end -- (no negative zero)
  ts = ts or {}
  local n = 1
  if lo >= 0 then
    if lo == 0 then lo = 0.0 end
    ts[1] = lo
    if two then
      ts[2] = hi
      n = 2
    end
  else
    ts[1] = hi
  end
  for i = #ts, n + 1, -1 do ts[i] = nil end
  return ts, n
end

--- The hits of the ray from (x, y) along (dx, dy) (arguments valid) on shape `s`, as
--- distances along the normalised direction, ascending: `ts` (filled from index 1, entries
--- past n cleared; a new table when nil) and the count n (1 or 2); nil, 0 on a miss.
---@param s strike.Shape
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param ts number[]|nil
---@return number[]|nil ts, integer n
function ray.intersections(s, x, y, dx, dy, ts)
  local ux, uy = unit(dx, dy)
  return fill(s, x, y, ux, uy, ts)
end

--- True when the ray hits the shape (arguments valid). Allocates nothing.
---@param s strike.Shape
---@param x number
---@param y number
---@param dx number
---@param dy number
---@return boolean
function ray.intersects(s, x, y, dx, dy)
  local ux, uy = unit(dx, dy)
  return clip(s, x, y, ux, uy) ~= nil
end

--- The first hit at a distance of at most maxDistance along the ray from (ox, oy) with
--- unit direction (ux, uy): distance, hit point, outward unit normal there; or nil.
--- Polygons: the normal of the face that bounds the interval at that end (the entering
--- face; the leaving one for a ray starting inside). Circles: (hit - centre) / r.
--- Edges: the side facing the ray's origin; for a collinear ray, the segment's direction
--- at that end (-u at the near end, +u at the far end for a ray starting on the segment).
---@param s strike.Shape
---@param ox number
---@param oy number
---@param ux number
---@param uy number
---@param maxDistance number
---@return number|nil distance, number x, number y, number nx, number ny
function ray.cast(s, ox, oy, ux, uy, maxDistance)
  local lo, hi, nxLo, nyLo, nxHi, nyHi = span(s, ox, oy, ux, uy)
  if not lo then return nil end
  local t, nx, ny = lo, nxLo, nyLo
  if lo + shiftT < 0 then t, nx, ny = hi, nxHi, nyHi end
  local d = t + shiftT -- (the distance from the ray's own origin)
  if d > maxDistance or d == huge then return nil end
  castFar, castNear = shiftFar, shiftNear + t
  if d == 0 then d = 0.0 end
  return d, shiftX + t * ux, shiftY + t * uy, nx, ny
end
local cast = ray.cast

--- rayCast on one shape (arguments valid): see ray.cast; (dx, dy) need not be a unit vector.
---@param s strike.Shape
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param maxDistance number
---@return number|nil distance, number x, number y, number nx, number ny
function ray.rayCast(s, x, y, dx, dy, maxDistance)
  local ux, uy = unit(dx, dy)
  return cast(s, x, y, ux, uy, maxDistance)
end

-- The unit direction and length of the segment p1 -> p2, or nil when p1 == p2.
local function segmentRay(x1, y1, x2, y2)
  local dx, dy = (x2 + 0.0) - x1, (y2 + 0.0) - y1 -- (floats: integer differences wrap on Lua 5.3+)
  if dx == 0 and dy == 0 then return nil end
  local k = 1
  if dx - dx ~= 0 or dy - dy ~= 0 then -- the difference overflows: halve first
    dx, dy, k = x2 * 0.5 - x1 * 0.5, y2 * 0.5 - y1 * 0.5, 2
  end
  local ux, uy, l = unit(dx, dy)
  return ux, uy, l * k
end

--- segmentCast on one shape (arguments valid): the first hit of the segment from
--- (x1, y1) to (x2, y2), as ray.cast with the segment's length as maxDistance; nil when
--- p1 == p2.
---@param s strike.Shape
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
---@return number|nil distance, number x, number y, number nx, number ny
function ray.segmentCast(s, x1, y1, x2, y2)
  local ux, uy, l = segmentRay(x1, y1, x2, y2)
  if not ux then return nil end
  return cast(s, x1, y1, ux, uy, l)
end

-- Leaf lists (colliders) ---------------------------------------------------------------
--
-- Seams. The faces of a leaf whose `_seams` is set (a piece of a compound, such as the
-- pieces of S.trikers.Concave; strike/base/VertexShape.lua) may be cuts inside the compound
-- rather than surfaces, and a ray crossing a cut is inside the compound on both sides: the
-- queries below report the crossings of the outline only. Each leaf takes the usual path;
-- only a leaf that was hit and has `_seams` is asked again (seamSpan): which faces bound its
-- interval (polygonClip leaves them in clipIn, clipOut), and whether each end lies on a seam
-- part of its face, away from that part's ends (which are outline vertices). An end on a
-- seam is dropped; for rayCast, the leaf's other end, if not behind the origin, may still
-- be a hit (a ray starting inside an L leaves it through the outline, not through the cut).

-- Slack of the seam test for a ray's hit point, per unit of distance from where the kernel
-- measured (the point's error grows with it).
local SEAM_SLACK = 1e-12

-- Is the end of the last span at the kernel's distance t, bounded by the face whose record
-- starts at slot k (0: none), on a seam part of that face?
local function seamEnd(s, k, t, ux, uy)
  if k == 0 then return false end
  local i = (k - BASE) / STRIDE
  if not s._seams[i] then return false end
  return s:_onSeam(i, shiftX + t * ux, shiftY + t * uy, SEAM_SLACK * abs(t))
end

-- span, and whether its ends lo and hi are seam crossings (two more values); nil on a miss.
local function seamSpan(s, ox, oy, ux, uy)
  clipIn, clipOut = 0, 0 -- (a kernel other than polygonClip leaves them: no face, no seam)
  local lo, hi, nxLo, nyLo, nxHi, nyHi = span(s, ox, oy, ux, uy)
  if not lo then return nil end
  local fin, fout = clipIn, clipOut
  return lo, hi, nxLo, nyLo, nxHi, nyHi, seamEnd(s, fin, lo, ux, uy), seamEnd(s, fout, hi, ux, uy)
end

-- fill's list `ts` for a leaf with seams (hit), without the seam crossings; nil when none is
-- left.
local function dropSeams(s, ox, oy, ux, uy, ts)
  local lo, _, _, _, _, _, seamLo, seamHi = seamSpan(s, ox, oy, ux, uy)
  if not lo then return ts end -- (fill found a hit; the same span cannot miss)
  -- fill's order: ts[1] is lo's end unless lo is behind the origin (then hi's), ts[2] hi's
  local n = #ts
  if n == 2 and seamHi then
    ts[2] = nil
    n = 1
  end
  local firstSeam = seamHi
  if lo + shiftT >= 0 then firstSeam = seamLo end
  if firstSeam then
    ts[1], ts[2] = ts[2], nil
    n = n - 1
  end
  if n == 0 then return nil end
  return ts
end

-- Does the ray (hitting the leaf s, which has seams) cross its outline part at t >= 0?
local function seamHit(s, ox, oy, ux, uy)
  local lo, _, _, _, _, _, seamLo, seamHi = seamSpan(s, ox, oy, ux, uy)
  if not lo then return false end
  return (lo + shiftT >= 0 and not seamLo) or not seamHi
end

-- ray.cast for a leaf with seams: the first end at t >= 0 that is not a seam crossing.
local function seamCast(s, ox, oy, ux, uy, maxDistance)
  local lo, hi, nxLo, nyLo, nxHi, nyHi, seamLo, seamHi = seamSpan(s, ox, oy, ux, uy)
  if not lo then return nil end
  local t, nx, ny
  if lo + shiftT >= 0 and not seamLo then
    t, nx, ny = lo, nxLo, nyLo
  elseif not seamHi then
    t, nx, ny = hi, nxHi, nyHi
  else
    return nil
  end
  local d = t + shiftT
  if d > maxDistance or d == huge then return nil end
  castFar, castNear = shiftFar, shiftNear + t
  if d == 0 then d = 0.0 end
  return d, shiftX + t * ux, shiftY + t * uy, nx, ny
end

--- The hits on every leaf that is hit: a new table { [shape] = { t1, t2 } } (or { t1 }),
--- or nil when no leaf is hit. Crossings of seams are left out (a leaf whose hits were all
--- on seams is absent). Arguments valid.
---@param leaves strike.Shape[]
---@param n integer
---@param x number
---@param y number
---@param dx number
---@param dy number
---@return table|nil
function ray.leavesIntersections(leaves, n, x, y, dx, dy)
  local ux, uy = unit(dx, dy)
  local result
  for i = 1, n do
    local s = leaves[i]
    local ts = fill(s, x, y, ux, uy, nil) -- (a new table only on a hit)
    if ts and s._seams then ts = dropSeams(s, x, y, ux, uy, ts) end
    if ts then
      result = result or {}
      result[s] = ts
    end
  end
  return result
end

--- True when the ray hits some leaf, not counting crossings of seams (a ray starting inside
--- a compound crosses its outline on the way out). Arguments valid; allocates nothing.
---@param leaves strike.Shape[]
---@param n integer
---@param x number
---@param y number
---@param dx number
---@param dy number
---@return boolean
function ray.leavesIntersect(leaves, n, x, y, dx, dy)
  local ux, uy = unit(dx, dy)
  for i = 1, n do
    local s = leaves[i]
    if clip(s, x, y, ux, uy) and (not s._seams or seamHit(s, x, y, ux, uy)) then return true end
  end
  return false
end

-- The first hit over the leaves (unit direction): ray.cast's values and the leaf; on ties
-- the first leaf in order. Crossings of seams are not hits.
local function leavesCast(leaves, n, ox, oy, ux, uy, maxDistance)
  local bt, bx, by, bnx, bny, best
  local bFar, bNear = 0, 0 -- the best hit's distance as the unrounded sum bFar + bNear
  for i = 1, n do
    local s = leaves[i]
    local t, hx, hy, nx, ny = cast(s, ox, oy, ux, uy, maxDistance)
    if t and s._seams then t, hx, hy, nx, ny = seamCast(s, ox, oy, ux, uy, maxDistance) end
    -- (equal distances may differ below their rounding when the origin is far: compare the
    -- unrounded sums, so that the nearer leaf still wins)
    if t and (not best or t < bt or (t == bt and (castFar - bFar) + (castNear - bNear) < 0)) then
      bt, bx, by, bnx, bny, best = t, hx, hy, nx, ny, s
      bFar, bNear = castFar, castNear
      maxDistance = t
    end
  end
  if not best then return nil end
  return bt, bx, by, bnx, bny, best
end

--- rayCast over a leaf list (arguments valid): distance, hit point, normal and the leaf
--- hit first (ties: the first leaf in order), or nil. Crossings of seams are not hits.
---@param leaves strike.Shape[]
---@param n integer
---@param x number
---@param y number
---@param dx number
---@param dy number
---@param maxDistance number
---@return number|nil distance, number x, number y, number nx, number ny, strike.Shape shape
function ray.leavesRayCast(leaves, n, x, y, dx, dy, maxDistance)
  local ux, uy = unit(dx, dy)
  return leavesCast(leaves, n, x, y, ux, uy, maxDistance)
end

--- segmentCast over a leaf list (arguments valid); nil when p1 == p2.
---@param leaves strike.Shape[]
---@param n integer
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
---@return number|nil distance, number x, number y, number nx, number ny, strike.Shape shape
function ray.leavesSegmentCast(leaves, n, x1, y1, x2, y2)
  local ux, uy, l = segmentRay(x1, y1, x2, y2)
  if not ux then return nil end
  return leavesCast(leaves, n, x1, y1, ux, uy, l)
end

return ray
