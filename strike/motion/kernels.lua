--- Motion kernels on two leaf shapes (refreshed, read through the data contract of
--- base/layout.lua): the distance between them, and the time of impact when one of them
--- translates. S.weep and S.eparation (motion/sweep.lua, motion/separation.lua) run them over
--- every pair of two bodies' leaves. They allocate nothing.
---
--- Every built-in leaf is a *core* and a radius: a convex polygon, a segment, or one point
--- (a circle's or point's centre: its X, Y slots, read as a one-vertex core), grown by the
--- radius in slot R (a circle's radius, a rounded shape's, else 0). Two leaves touch when the
--- distance between their cores reaches the sum of their radii.
---
--- Time of impact: A moves by t (dx, dy), t in [0, 1], B stays. The answer is the first t at
--- which they would begin to overlap: a pair that only touches at the start, or grazes a
--- corner, and never overlaps is no hit; a pair touching at the start and moving into each
--- other is a hit at t = 0.
---  * Sharp pairs (both radii 0): the ray t (dx, dy) against the Minkowski difference
---    M = B - A, which A's translation reaches exactly when they overlap. M is the
---    intersection of the half-planes n . s <= h(n) = max over B of n . b - min over A of n . a
---    over the faces of both cores (B's normals, A's negated: the axes of the SAT, sat.lua),
---    plus each segment core's two directions and, for two points, the two coordinate axes
---    (M is then a segment or a point, which the faces alone do not bound). The ray is
---    clipped against them as a ray against a polygon (M. Cyrus and J. Beck, "Generalized
---    two- and three-dimensional clipping", Computers & Graphics 3(1), 1978, as
---    collide/ray.lua does): the interval [lo, hi] of t inside M. A hit needs lo < hi (an
---    interior to enter; where a segment core's faces bound it, by more than the ties'
---    tolerance: see sharpToi), hi > 0 and lo <= 1; t = max(lo, 0). The face that gave lo is the
---    hit's normal, from B toward A. An h within the touching tolerance of 0 (round-off of a
---    touching start: see Tolerances) counts as 0, so that a pair touching at the start and
---    moving apart is no hit, and one moving in is a hit at t = 0. A move parallel to a face
---    (|n . d| within the rounding of d) is inside its half-plane for the whole move when
---    h > 0, else never: with no tolerance, as S.triking decides (the same h, to the last bit),
---    so that a body level with a face within round-off is not let into the body beyond it.
---  * Rounded pairs: the first contact of two convex sets at a distance R > 0 is between a
---    vertex of one core and an edge (or the vertex) of the other, so the answer is the
---    earliest of the rays from every core vertex of A (along (dx, dy)) against the capsule
---    of radius R about every edge of B, and from every vertex of B (along -(dx, dy))
---    against the capsules about A's edges; each capsule as its two discs and the two sides
---    of its rectangle (C. Ericson, Real-Time Collision Detection, 2005, 5.3.2 for the discs,
---    in the numerically stable form of collide/ray.lua). The normal is from the core point
---    of B to the core point of A, at distance R; for a hit inside an edge, the edge's own
---    normal (the closest point on a long edge is rounded relative to its ends, which may be
---    far). A ray tangent to a disc within the rounding of its formula is no hit: a body that
---    fits a gap exactly passes the corner at its rim.
---
--- Tolerances. They are relative to the moving leaf's neighbourhood, not to the other leaf:
--- the touching tolerance of a pair is TIE times the smaller extent of the two leaves (width
--- plus height of its bounds) plus limits.ROUND times the largest coordinate of the box A
--- sweeps (the rounding of the coordinates there). So a leaf a millionth across meets a face
--- a million across at the right time, where a tolerance relative to the huge leaf's
--- coordinates found it touching (t = 0) or missed. Ties in t are within the tolerance over
--- the move's length. A move within PARALLEL of a face's direction (|n . d| <= PARALLEL |d|,
--- the rounding of a direction made parallel to a face, as a slide's is) runs along it.
---
--- Corners. When two faces of M that are not parallel give the same lo (within TIE), the
--- sharp hit met a corner of M: any normal between the two is right. The kernel then picks
--- the one the move grazes most (the smallest |n . d|: the move slides past the corner), and
--- flags the hit a corner, so that a caller choosing among hits at the same time can prefer
--- a face (a box landing exactly on the seam between two tiles meets a corner of the second
--- tile and the face of the first: the face wins; see sweep.lua). A rounded hit at a vertex of
--- B's core is a corner too (a capsule over the seam meets the first tile's corner, with a
--- normal tilted by how far past it the capsule is, and the second tile's face at the same
--- time), and within a pair a hit inside an edge of B beats one at its vertex.
---
--- Chain segments (base/ChainSegment.lua) are one-sided as in collide/chain.lua: a leaf
--- whose centroid starts behind the segment's line never meets it, and a hit counts only
--- when its normal (from the segment toward the other leaf) is one the segment may push
--- along (chain.admissible: its own normal, or within a convex corner's cone); at a corner
--- of a sharp pair, an end's direction is replaced by the neighbour's normal at a convex
--- corner and left to the neighbour at a flat or concave one. Ghost vertices then make a
--- chain as smooth to a sweep as to the narrow phase. A leaf already partly through a
--- segment at the start passes on (a one-way platform jumped into from below). Two chain
--- segments never meet.
---
--- Open ends. An open end (no neighbour) is the edge of a platform, never a wall. It meets
--- a leaf only when the leaf does not move toward the segment's free side (d . n <= 0: for a
--- floor, a leaf that does not rise), and then only along a normal tilted toward the free
--- side, never along the segment's own direction (the end's outward tangent, the far side
--- of its cone: a hit along it is a leaf meeting the end with a side that reaches across the
--- line). A leaf falling onto the end from above lands on it (along n, or coming down beyond
--- the end along a normal of the end's cone: a rounded leaf rests on it or rolls off it); a
--- leaf jumping up past the end, or beside it with a side across the line, passes it as it
--- passes a segment it is partly through. (The narrow phase, collide/chain.lua, keeps the
--- whole cone: it knows no motion.)
local ROOT = (...):match('^(.-)%.motion%.[^%.]+$')
local layout = require(ROOT .. '.base.layout')
local limits = require(ROOT .. '.limits')
local admissible = require(ROOT .. '.collide.chain').admissible

local COUNT, HALF, X, Y, R = layout.COUNT, layout.HALF, layout.X, layout.Y, layout.R
local MINX, MINY, MAXX, MAXY = layout.MINX, layout.MINY, layout.MAXX, layout.MAXY
local STRIDE, FIRST, VY, NX, NY, D = layout.STRIDE, layout.FIRST, layout.VY, layout.NX, layout.NY, layout.D
local HASPREV, HASNEXT, CONVEX1, CONVEX2 = layout.HASPREV, layout.HASNEXT, layout.CONVEX1, layout.CONVEX2
local G1X, G1Y, G2X, G2Y = layout.G1X, layout.G1Y, layout.G2X, layout.G2Y
local P1 = layout.base(1)
local sqrt, huge, max = math.sqrt, math.huge, math.max
-- chain.lua's slack on the sines of its admissibility tests.
local CHAIN_TOL = 1e-12

-- A one-vertex core is read at its X, Y slots as if they were a vertex record.
assert(X + VY == Y, 'motion/kernels.lua: a centre must read as a vertex record')

local kernels = {}

--- Relative tolerance of touching and ties: TIE times the pair's smaller extent, plus the
--- rounding of the coordinates (see the header, Tolerances).
kernels.TIE = 1e-11
local ROUND = limits.ROUND
--- A move with |n . d| <= PARALLEL |d| runs along the axis n (see the header).
kernels.PARALLEL = 2 ^ -50
local PARALLEL = kernels.PARALLEL
--- A pair touching at the start is a hit when the move goes into it: when d . n < -APPROACH
--- |d|, n the normal at the start (a sine: moves closer to the touching face than that
--- slide along it).
kernels.APPROACH = 1e-9
local APPROACH = kernels.APPROACH

-- The slots of a core's first and last vertex record, and its vertex count.
local function span(s)
  local n = s[COUNT]
  if n then return FIRST, FIRST + STRIDE * (n - 1), n end
  return X, X, 1
end
--- span(s): the slots of a core's first and last vertex record, and its vertex count.
---@param s table
---@return integer k0
---@return integer k1
---@return integer n
kernels.span = span

local function minProj(s, k0, k1, ux, uy)
  local m = huge
  for k = k0, k1, STRIDE do
    local p = ux * s[k] + uy * s[k + VY]
    if p < m then m = p end
  end
  return m
end

-- Both at once: the least and the greatest projection.
local function minMaxProj(s, k0, k1, ux, uy)
  local lo_, hi_ = huge, -huge
  for k = k0, k1, STRIDE do
    local p = ux * s[k] + uy * s[k + VY]
    if p < lo_ then lo_ = p end
    if p > hi_ then hi_ = p end
  end
  return lo_, hi_
end

--- The largest coordinate magnitude of the box that leaf A sweeps moving by (dx, dy): the
--- coordinates whose rounding the tolerance of its pairs must cover (see the header,
--- Tolerances: TIE times the smaller extent of the pair, plus ROUND times this).
---@param A table
---@param dx number
---@param dy number
---@return number
function kernels.reach(A, dx, dy)
  local x0, y0, x1, y1 = A[MINX], A[MINY], A[MAXX], A[MAXY]
  -- (the box at the start and at the end, whose union is the box swept; no branch on the
  -- move's direction, for LuaJIT's traces)
  return max(-x0, x1, -y0, y1, -x0 - dx, x1 + dx, -y0 - dy, y1 + dy)
end


------------------------------------------------------------------ the axes of a pair

-- State of the axis scan: `mode` 1 clips the ray (toi), 2 finds the smallest h (overlap).
local mode, mdx, mdy, tieH, tieT, par = 1, 0, 0, 0, 0, 0
local lo, hi, dead = -huge, huge, false
-- The exit time of a segment core's faces (segExit: the axes being stepped are them), kept
-- apart from hi: a segment has no width, so a core crossing its line leaves it through one
-- face when it enters through the other, the same time up to rounding (see sharpToi).
local hiSeg, segExit = huge, false
local bux, buy, bclass, btag, bdn, bcorner = 0, 0, 0, 0, 0, false
local minH = huge

-- One axis (ux, uy) with its h: class 1 a face of B (tag: its record's slot), 2 a face of
-- A, 3 a direction of a segment (tag 1: B's p1 end, 2: B's p2 end, 0: A's) or a coordinate
-- axis.
local function step(ux, uy, h, class, tag)
  if mode == 2 then
    if h < minH then minH, bux, buy = h, ux, uy end
    return
  end
  local dn = mdx * ux + mdy * uy
  if dn < -par then
    if h <= tieH and h >= -tieH then h = 0 end
    local te = h / dn
    if te > lo + tieT then
      lo, bux, buy, bclass, btag, bdn, bcorner = te, ux, uy, class, tag, dn, false
    elseif te >= lo - tieT then -- a tie: the same face seen from both shapes, or a corner
      if ux * buy - uy * bux > 1e-9 or ux * buy - uy * bux < -1e-9 or ux * bux + uy * buy < 0 then
        bcorner = true
      end
      local better
      if class == 3 or bclass == 3 then better = bclass == 3 and class ~= 3 else better = -dn < -bdn end
      if better then bux, buy, bclass, btag, bdn = ux, uy, class, tag, dn end
      if te > lo then lo = te end
    end
  elseif dn > par then
    if h <= tieH and h >= -tieH then h = 0 end
    local tx = h / dn
    if segExit then
      if tx < hiSeg then hiSeg = tx end
    elseif tx < hi then
      hi = tx
    end
  elseif h <= 0 then
    -- Along the axis (within the rounding of a direction: par): inside its slab for the whole
    -- move or never, as S.triking finds it, to the last bit. (A tolerance here would let a body
    -- level with a face within round-off slide into the body beyond it, overlapping it by as
    -- much; the skin keeps a body that stopped well clear of the faces it slides along.)
    dead = true
  end
end

-- The directions of a segment core (slots k0, k1), as axes for the pair: `onB` when the
-- segment is B's.
local function segmentAxes(seg, k0, k1, other, o0, o1, onB)
  local ex, ey = seg[k1] - seg[k0], seg[k1 + VY] - seg[k0 + VY]
  local l = sqrt(ex * ex + ey * ey)
  if not (l > 0) then return false end -- luacheck: ignore 581 (NaN reads as no hit)
  ex, ey = ex / l, ey / l
  -- (h along e is B's greatest projection less A's least; along -e, A's greatest less B's least)
  local slo, shi = minMaxProj(seg, k0, k1, ex, ey)
  local olo, ohi = minMaxProj(other, o0, o1, ex, ey)
  if onB then
    step(ex, ey, shi - olo, 3, 2)
    step(-ex, -ey, ohi - slo, 3, 1)
  else
    step(ex, ey, ohi - slo, 3, 0)
    step(-ex, -ey, shi - olo, 3, 0)
  end
  return true
end

-- Every axis of the pair (see the header), through step.
local function scan(A, B)
  local a0, a1, na = span(A)
  local b0, b1, nb = span(B)
  -- (a centrally symmetric core, HALF > 0, has its faces in opposite pairs k, k + HALF: one
  -- pass over the other shape gives the least projection for face k and the greatest, which
  -- is minus the least for face k + HALF)
  local half = nb >= 4 and B[HALF] or 0
  if half > 0 then
    local opp = STRIDE * half
    for k = b0, b0 + opp - STRIDE, STRIDE do
      local ux, uy = B[k + NX], B[k + NY]
      local lo_, hi_ = minMaxProj(A, a0, a1, ux, uy)
      step(ux, uy, B[k + D] - lo_, 1, k)
      step(B[k + opp + NX], B[k + opp + NY], B[k + opp + D] + hi_, 1, k + opp)
    end
  elseif nb >= 2 then
    segExit = nb == 2
    for k = b0, b1, STRIDE do
      local ux, uy = B[k + NX], B[k + NY]
      step(ux, uy, B[k + D] - minProj(A, a0, a1, ux, uy), 1, k)
    end
    segExit = false
  end
  half = na >= 4 and A[HALF] or 0
  if half > 0 then
    local opp = STRIDE * half
    for k = a0, a0 + opp - STRIDE, STRIDE do
      local mx, my = A[k + NX], A[k + NY]
      local lo_, hi_ = minMaxProj(B, b0, b1, mx, my)
      step(-mx, -my, A[k + D] - lo_, 2, k)
      step(-A[k + opp + NX], -A[k + opp + NY], A[k + opp + D] + hi_, 2, k + opp)
    end
  elseif na >= 2 then
    segExit = na == 2
    for k = a0, a1, STRIDE do
      local mx, my = A[k + NX], A[k + NY]
      step(-mx, -my, A[k + D] - minProj(B, b0, b1, mx, my), 2, k)
    end
    segExit = false
  end
  local pointA = na == 1 or (na == 2 and not segmentAxes(A, a0, a1, B, b0, b1, false))
  local pointB = nb == 1 or (nb == 2 and not segmentAxes(B, b0, b1, A, a0, a1, true))
  if pointA and pointB then
    for axis = 0, 1 do -- x, then y
      local ux, uy = 1 - axis, axis
      local alo, ahi = minMaxProj(A, a0, a1, ux, uy)
      local blo, bhi = minMaxProj(B, b0, b1, ux, uy)
      step(ux, uy, bhi - alo, 3, 0)
      step(-ux, -uy, ahi - blo, 3, 0)
    end
  end
end

--- The largest penetration of the two cores over the axes of the pair: > 0 when the cores
--- overlap (their SAT depth), <= 0 when an axis separates them (by at least its minus); and
--- that axis, a unit normal from B toward A.
---@param A table
---@param B table
---@return number h
---@return number ux
---@return number uy
function kernels.coreOverlap(A, B)
  mode, minH, bux, buy = 2, huge, 0, 0
  scan(A, B)
  return minH, bux, buy
end

--- The point of a leaf farthest along the unit vector (ux, uy): its core's support, grown by
--- its radius.
---@param s table
---@param ux number
---@param uy number
---@return number x
---@return number y
function kernels.support(s, ux, uy)
  local k0, k1 = span(s)
  local best, bx, by = -huge, 0, 0
  for k = k0, k1, STRIDE do
    local p = ux * s[k] + uy * s[k + VY]
    if p > best then best, bx, by = p, s[k], s[k + VY] end
  end
  local r = s[R]
  return bx + ux * r, by + uy * r
end

------------------------------------------------------------------ distance

-- The closest point to (px, py) on the segment (ax, ay)-(bx, by), the squared distance, and
-- the point's parameter along the segment (0 at a, 1 at b).
local function closest(px, py, ax, ay, bx, by)
  local ex, ey = bx - ax, by - ay
  local l2 = ex * ex + ey * ey
  local u = 0
  if l2 > 0 then
    u = ((px - ax) * ex + (py - ay) * ey) / l2
    if u < 0 then u = 0 elseif u > 1 then u = 1 end
  end
  local qx, qy = ax + u * ex, ay + u * ey
  local dx, dy = px - qx, py - qy
  return qx, qy, dx * dx + dy * dy, u
end

-- The edges of a core: its records' slots k0 .. k1 give edges (k, next k), wrapping for
-- three or more vertices; a segment has one edge, a point one degenerate edge.
local function lastEdge(k0, k1, n)
  if n >= 3 then return k1 end
  return k0
end

-- Best pair so far of nearest: squared distance, the point on A, the point on B.
local nd2, nax, nay, nbx, nby = huge, 0, 0, 0, 0

local function nearestOneWay(P, p0, p1, Q, q0, q1, nq, flip)
  local qlast = lastEdge(q0, q1, nq)
  for k = p0, p1, STRIDE do
    local px, py = P[k], P[k + VY]
    for j = q0, qlast, STRIDE do
      local j2 = j + STRIDE
      if j2 > q1 then j2 = q0 end
      if nq == 1 then j2 = j end
      local qx, qy, d2 = closest(px, py, Q[j], Q[j + VY], Q[j2], Q[j2 + VY])
      if d2 < nd2 then
        if flip then nd2, nax, nay, nbx, nby = d2, qx, qy, px, py else nd2, nax, nay, nbx, nby = d2, px, py, qx, qy end
      end
    end
  end
end

--- The distance between the cores of two leaves and their closest points (on A's core, then
--- on B's): exact for disjoint cores; 0 (with the first closest pair found) when they meet.
---@param A table
---@param B table
---@return number d
---@return number ax
---@return number ay
---@return number bx
---@return number by
function kernels.coreDistance(A, B)
  local a0, a1, na = span(A)
  local b0, b1, nb = span(B)
  nd2 = huge
  nearestOneWay(A, a0, a1, B, b0, b1, nb, false)
  nearestOneWay(B, b0, b1, A, a0, a1, na, true)
  if nd2 > 0 and kernels.coreOverlap(A, B) >= 0 then return 0, nax, nay, nbx, nby end
  return sqrt(nd2), nax, nay, nbx, nby
end
local coreDistance = kernels.coreDistance

------------------------------------------------------------------ time of impact

-- Where a hit is written: kernels.t, .nx, .ny (unit, from B toward A), .x, .y (the contact
-- point at t), .corner (see the header).
kernels.t, kernels.nx, kernels.ny, kernels.x, kernels.y, kernels.corner = 0, 0, 0, 0, 0, false
-- kernels.overlap: whether the last toi found the leaves overlapping at the start, beyond the
-- touching tolerance (a hit or not: the caller asks S.triking what to do).
kernels.overlap = false

-- The contact point of a sharp hit along (ux, uy) at t: the middle of the overlap of the
-- two shapes' extreme features on the touching line.
local function sharpPoint(A, B, t, dx, dy, ux, uy)
  local a0, a1 = span(A)
  local b0, b1 = span(B)
  local ox, oy = t * dx, t * dy
  local line = -minProj(B, b0, b1, -ux, -uy) -- (B's greatest projection)
  local mina = minProj(A, a0, a1, ux, uy) + ux * ox + uy * oy
  local tx, ty = -uy, ux
  local alo, ahi, blo, bhi = huge, -huge, huge, -huge
  for k = a0, a1, STRIDE do
    local x, y = A[k] + ox, A[k + VY] + oy
    if ux * x + uy * y <= mina + tieH then
      local p = tx * x + ty * y
      if p < alo then alo = p end
      if p > ahi then ahi = p end
    end
  end
  for k = b0, b1, STRIDE do
    local x, y = B[k], B[k + VY]
    if ux * x + uy * y >= line - tieH then
      local p = tx * x + ty * y
      if p < blo then blo = p end
      if p > bhi then bhi = p end
    end
  end
  local mid = ((alo > blo and alo or blo) + (ahi < bhi and ahi or bhi)) / 2
  return ux * line + tx * mid, uy * line + ty * mid
end

-- Whether the leaf A of the current toi moves toward the free side of the chain segment B
-- (d . n > 0), B having an open end (see the header, "Open ends"); false for other pairs.
local awayOpen = false

-- Is the unit normal (mx, my), from chain segment S toward A, one S may push A along?
-- chain.admissible, and toward an open end (see the header, "Open ends") only strictly
-- inside its cone (beyond chain.lua's slack from the tangent), and only when A does not
-- move toward the free side (awayOpen).
local function chainAllows(S, mx, my)
  if not admissible(S, mx, my) then return false end
  local c = S[P1 + NX] * my - S[P1 + NY] * mx -- (< 0 leans toward p1, > 0 toward p2)
  if c < -CHAIN_TOL and not S[HASPREV] then
    return not awayOpen and S[G1X] * my - S[G1Y] * mx > CHAIN_TOL -- cross(g1, m)
  elseif c > CHAIN_TOL and not S[HASNEXT] then
    return not awayOpen and mx * S[G2Y] - my * S[G2X] > CHAIN_TOL -- cross(m, g2)
  end
  return true
end

-- Sharp pair: false, or true with the hit in `kernels` (B may be a chain segment; A not).
local function sharpToi(A, B, dx, dy, tol)
  mode, mdx, mdy, tieH = 1, dx, dy, tol
  local dl = sqrt(dx * dx + dy * dy)
  tieT, par = dl > 0 and tol / dl or 0, PARALLEL * dl
  lo, hi, dead, bclass, bcorner, hiSeg = -huge, huge, false, 0, false, huge
  scan(A, B)
  local hiAll = hi < hiSeg and hi or hiSeg
  -- (overlapping at the start, beyond round-off: the caller's S.triking decides)
  if not dead and lo < -tieT and hiAll > tieT and B._kind ~= 'chain' then kernels.overlap = true end
  -- The cores meet for a while: lo < hi, and by more than the ties' tolerance before a
  -- segment's faces let go (a segment has no width: a point, or a segment parallel to it,
  -- crossing its line enters through one face at the time it leaves through the other, the
  -- same time but for rounding; M has no interior there, and no area between the two to
  -- overlap, so that is no hit, as S.triking never finds them colliding. Strictly lo < hi
  -- let rounding decide: a point met a chain segment far from the origin or passed through
  -- it by the last bit of its ends.)
  local meet = lo < hi and lo < hiSeg - tieT
  -- luacheck: ignore 581 (NaN reads as no hit)
  if dead or bclass == 0 or not meet or not (hiAll > 0) or not (lo <= 1) then return false end
  local ux, uy = bux, buy
  if B._kind == 'chain' then -- a chain segment: its own normal, or a convex corner's cone
    if lo < -tieT then return false end -- (partly through it already: it lets A pass)
    if bclass == 1 then
      if btag ~= P1 then return false end -- its back face
    elseif bclass == 3 then
      if btag == 1 then
        if not B[CONVEX1] then return false end
        if not B[HASPREV] then return false end -- (an open end: never along its tangent)
        ux, uy = B[G1X], B[G1Y]
      elseif btag == 2 then
        if not B[CONVEX2] then return false end
        if not B[HASNEXT] then return false end
        ux, uy = B[G2X], B[G2Y]
      end
    elseif not chainAllows(B, ux, uy) then
      return false
    end
  end
  local t = lo > 0 and lo or 0
  kernels.t, kernels.nx, kernels.ny, kernels.corner = t, ux, uy, bcorner
  kernels.x, kernels.y = sharpPoint(A, B, t, dx, dy, bux, buy)
  return true
end

-- The entry time of the point p moving by (dx, dy) into the disc of radius r about c, from
-- outside; huge when it misses or only grazes: when its line passes the circle within the
-- rounding of this formula (disc = a (r^2 - m^2), m the line's distance from c, each term
-- rounded relative to a r^2: a line tangent to the circle, as a body that fits a gap exactly
-- passes a corner, is no hit).
local function discEntry(px, py, dx, dy, cx, cy, r)
  local mx, my = px - cx, py - cy
  local b = mx * dx + my * dy
  if b >= 0 then return huge end
  local a = dx * dx + dy * dy
  local cr = mx * dy - my * dx
  local ar2 = a * r * r
  local disc = ar2 - cr * cr
  if not (disc > ar2 * ROUND) then return huge end -- luacheck: ignore 581 (NaN reads as no hit)
  return (mx * mx + my * my - r * r) / (-b + sqrt(disc))
end

-- The entry time of p moving by (dx, dy) into the capsule of radius r about the segment
-- (ax, ay)-(bx, by), from outside; huge when it misses.
local function capsuleEntry(px, py, dx, dy, ax, ay, bx, by, r)
  local best = discEntry(px, py, dx, dy, ax, ay, r)
  local ex, ey = bx - ax, by - ay
  local l2 = ex * ex + ey * ey
  if l2 > 0 then
    local t2 = discEntry(px, py, dx, dy, bx, by, r)
    if t2 < best then best = t2 end
    local l = sqrt(l2)
    local nx, ny = -ey / l, ex / l
    local s, dn = nx * (px - ax) + ny * (py - ay), nx * dx + ny * dy
    if s < 0 then s, dn = -s, -dn end
    if s > r and dn < 0 then
      local t = (r - s) / dn
      if t < best then
        local u = (ex * (px + t * dx - ax) + ey * (py + t * dy - ay)) / l2
        if u >= 0 and u <= 1 then best = t end
      end
    end
  end
  return best
end

-- Rounded pair's best hit so far (rcorner: it is at a vertex of B's core).
local rt, rnx, rny, rx, ry, rcorner = huge, 0, 0, 0, 0, false

-- Rays from P's core vertices (moving by (dx, dy)) against the capsules about Q's edges.
-- `flip`: P is B (moving by -d), Q is A. A hit at a vertex of B's core (an end of B's edge,
-- or any hit from B's side) is a corner (see the header): among hits at the same time
-- (within tieT, set by roundToi), one on the inside of an edge of B is preferred.
local function roundOneWay(P, Q, dx, dy, r, rB, flip, chainSeg)
  local p0, p1 = span(P)
  local q0, q1, nq = span(Q)
  local qlast = lastEdge(q0, q1, nq)
  for k = p0, p1, STRIDE do
    local px, py = P[k], P[k + VY]
    for j = q0, qlast, STRIDE do
      local j2 = j + STRIDE
      if j2 > q1 then j2 = q0 end
      if nq == 1 then j2 = j end
      local ax, ay, bx, by = Q[j], Q[j + VY], Q[j2], Q[j2 + VY]
      local t = capsuleEntry(px, py, dx, dy, ax, ay, bx, by, r)
      if t <= 1 and t < rt + tieT then
        local hx, hy = px + t * dx, py + t * dy
        local qx, qy, _, u = closest(hx, hy, ax, ay, bx, by)
        local corner = flip or u <= 0 or u >= 1
        if t < rt - tieT or (rcorner and not corner) then
          local nx, ny = hx - qx, hy - qy
          local l = sqrt(nx * nx + ny * ny)
          if l > 0 then
            if u > 0 and u < 1 then
              -- (inside the edge: its own normal, toward the point. The closest point is
              -- rounded relative to the edge's ends, which may be far on a huge shape; the
              -- normal of an axis-aligned edge is then exactly axis-aligned)
              local ex, ey = bx - ax, by - ay
              local el = sqrt(ex * ex + ey * ey)
              local mx, my = -ey / el, ex / el
              if mx * nx + my * ny < 0 then mx, my = -mx, -my end
              nx, ny = mx, my
            else
              nx, ny = nx / l, ny / l
            end
            if flip then nx, ny = -nx, -ny end -- (from B toward A)
            if not chainSeg or chainAllows(chainSeg, nx, ny) then
              rt, rnx, rny, rcorner = t, nx, ny, corner
              if flip then rx, ry = px + nx * rB, py + ny * rB else rx, ry = qx + nx * rB, qy + ny * rB end
            end
          end
        end
      end
    end
  end
end

-- Rounded pair (A[R] + B[R] > 0): false, or true with the hit in `kernels`.
local function roundToi(A, B, dx, dy, tol)
  local r, rB = A[R] + B[R], B[R]
  local chainSeg = B._kind == 'chain' and B or false
  local d, ax, ay, bx, by = coreDistance(A, B)
  if d < r - tol then -- (overlapping: the caller's S.triking decides)
    kernels.overlap = B._kind ~= 'chain'
    return false
  end
  if d <= r + tol then -- touching at the start: a hit when the move goes in
    if not (d > 0) then return false end -- luacheck: ignore 581 (NaN reads as no hit)
    local nx, ny = (ax - bx) / d, (ay - by) / d
    -- (going in by more than round-off: a normal found from closest points is only that
    -- exact, and a move along the touching face must not stop)
    -- luacheck: ignore 581 (NaN reads as no hit)
    if not (dx * nx + dy * ny < -APPROACH * sqrt(dx * dx + dy * dy))
      or (chainSeg and not chainAllows(chainSeg, nx, ny)) then
      return false
    end
    kernels.t, kernels.nx, kernels.ny, kernels.corner = 0, nx, ny, false
    kernels.x, kernels.y = bx + nx * rB, by + ny * rB
    return true
  end
  rt, rcorner = huge, false
  local dl = sqrt(dx * dx + dy * dy)
  tieT = dl > 0 and tol / dl or 0
  roundOneWay(A, B, dx, dy, r, rB, false, chainSeg)
  roundOneWay(B, A, -dx, -dy, r, rB, true, chainSeg)
  if rt == huge then return false end
  kernels.t, kernels.nx, kernels.ny, kernels.corner = rt, rnx, rny, rcorner
  kernels.x, kernels.y = rx, ry
  return true
end

--- The time of impact of leaf A moving by (dx, dy) against leaf B (see the header): false,
--- or true with the hit in kernels.t, .x, .y, .nx, .ny, .corner; kernels.overlap tells
--- whether they overlapped at the start (chain segments aside), when the answer is S.triking's. `tol` is the
--- touching tolerance (see the header, Tolerances).
---@param A table
---@param B table
---@param dx number
---@param dy number
---@param tol number
---@return boolean
function kernels.toi(A, B, dx, dy, tol)
  kernels.overlap = false
  local flip = A._kind == 'chain'
  if flip then
    if B._kind == 'chain' then return false end -- chain segments never meet
    A, B, dx, dy = B, A, -dx, -dy
  end
  if B._kind == 'chain' then -- one-sided: the other leaf's centroid must start in front
    local nx, ny = B[P1 + NX], B[P1 + NY]
    if nx * (A[X] - B[P1]) + ny * (A[Y] - B[P1 + VY]) < 0 then return false end
    awayOpen = dx * nx + dy * ny > 0 -- (read at open ends only)
  end
  local hit
  if A[R] + B[R] > 0 then hit = roundToi(A, B, dx, dy, tol) else hit = sharpToi(A, B, dx, dy, tol) end
  if hit and flip then
    local t = kernels.t
    kernels.nx, kernels.ny = -kernels.nx, -kernels.ny
    kernels.x, kernels.y = kernels.x - t * dx, kernels.y - t * dy
  end
  return hit
end

return kernels
