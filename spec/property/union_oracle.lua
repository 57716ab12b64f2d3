--- An independent oracle for the MTV between two compound bodies: the shortest
--- translation of b that separates ALL of a's members from ALL of b's members.
---
--- It never calls strike's collision code. A member is a plain description
---   { xs = {...}, ys = {...}, n = count, r = radius }
--- of a convex body: every point within r >= 0 of the convex hull of its n core vertices
--- (world coordinates, any order; n = 1 for a circle's centre, 2 for a capsule's segment).
---
--- Member pair (Ai, Bj) overlaps after b moves by t iff t lies in the interior of the
--- Minkowski difference Mij = Ai - Bj = hull{ai - bj} (+) disk(rAi + rBj). The answer is
--- the point of the complement of F = U int(Mij) nearest to the origin, when the origin is
--- in F (else the bodies do not collide: touching is not colliding).
---
--- Method: a directional search, certified by branch and bound over the angle.
---  * f(u), for a unit direction u, is the smallest s >= 0 with s u outside F. It is exact
---    per direction: the line s u meets every int(Mij) in an open interval of s (the
---    union of the line's intervals in the open disks at the core's vertices and in the
---    open slabs along its edges, or in the open core itself when the radius is 0), and
---    f(u) chains the intervals that cover 0. min over u of f is the answer, and every
---    f(u) is a free point, so any sample is an upper bound U.
---  * A lower bound of f over an angular interval [u1, u2] (width < pi): the annular
---    sector piece {s u : u in [u1, u2], s0 <= s < s1} lies in the convex hull of
---    s0 u1, s0 u2, s1 u1, s1 u2 and s1 sec(w/2) um (um the mid direction), so it is
---    inside int(Mij) when those points are; chaining such pieces from s = 0 proves the
---    whole sector up to some radius L is in F, so f >= L on the interval.
---  * Intervals whose bound is below U are split (and their mid directions sampled), until
---    every interval is certified within a relative 1e-10 of U (or is narrower than
---    1e-13 rad, which is recorded as the unresolved gap). f can jump (a direction may
---    pass through a narrow free pocket) and its minimum may be a sharp V at a corner of
---    the union; the bound does not care, so no local minimum is missed.
local brute = require('spec.property.brute')

local oracle = {}

local sqrt, huge, abs, cos, sin, pi = math.sqrt, math.huge, math.abs, math.cos, math.sin, math.pi
local min, max = math.min, math.max

local REL = 1e-10    -- certified relative accuracy of the length
local MIN_WIDTH = 1e-13 -- narrowest angular interval that is still split
local START = 32     -- initial angular intervals

-- The Minkowski difference of members a and b: core hull (positive winding) with unit
-- edge data, radius, a bounding circle, and the signed distance of the origin from it.
local function difference(a, b)
  local xs, ys, k = {}, {}, 0
  for i = 1, a.n do
    for j = 1, b.n do
      k = k + 1
      xs[k], ys[k] = a.xs[i] - b.xs[j], a.ys[i] - b.ys[j]
    end
  end
  local px, py, h = brute.hull(xs, ys, k)
  if h == 2 and px[1] == px[2] and py[1] == py[2] then h = 1 end
  local M = { px = px, py = py, h = h, r = (a.r or 0) + (b.r or 0) }
  -- unit edges (one for a segment), and their outward normals (right of the edge)
  local ex, ey, len, nx, ny = {}, {}, {}, {}, {}
  local m = h >= 3 and h or h - 1
  for i = 1, m do
    local j = i < h and i + 1 or 1
    local dx, dy = px[j] - px[i], py[j] - py[i]
    local l = sqrt(dx * dx + dy * dy)
    ex[i], ey[i], len[i] = dx / l, dy / l, l
    nx[i], ny[i] = dy / l, -dx / l
  end
  M.ex, M.ey, M.len, M.nx, M.ny, M.m = ex, ey, len, nx, ny, m
  local cx, cy = 0, 0
  for i = 1, h do cx, cy = cx + px[i], cy + py[i] end
  cx, cy = cx / h, cy / h
  local rho = 0
  for i = 1, h do
    local dx, dy = px[i] - cx, py[i] - cy
    rho = max(rho, sqrt(dx * dx + dy * dy))
  end
  M.cx, M.cy, M.rho = cx, cy, rho + M.r
  return M
end

-- Signed distance from (x, y) to the core of M: negative strictly inside a polygon core.
local function coreDistance(M, x, y)
  local px, py, h = M.px, M.py, M.h
  if h == 1 then
    local dx, dy = x - px[1], y - py[1]
    return sqrt(dx * dx + dy * dy)
  end
  local d, inside = huge, h >= 3
  for i = 1, M.m do
    local j = i < h and i + 1 or 1
    d = min(d, brute.pointSegDist(x, y, px[i], py[i], px[j], py[j]))
    if inside and brute.cross(px[i], py[i], px[j], py[j], x, y) <= 0 then inside = false end
  end
  return inside and -d or d
end

-- Signed distance from (x, y) to M itself (negative inside).
local function distance(M, x, y)
  return coreDistance(M, x, y) - M.r
end

--- The Minkowski differences of every member pair, as a list.
function oracle.differences(A, B)
  local list = {}
  for i = 1, #A do
    for j = 1, #B do list[#list + 1] = difference(A[i], B[j]) end
  end
  return list
end

-- The open interval (lo, hi) of s where s (ux, uy) is inside M; lo >= hi when empty.
local function lineInterval(M, ux, uy)
  local c = ux * M.cy - uy * M.cx
  if c >= M.rho or c <= -M.rho then return huge, -huge end
  local px, py, h, r = M.px, M.py, M.h, M.r
  local ex, ey = M.ex, M.ey
  if r == 0 then
    -- the open core: a polygon, else nothing
    if h < 3 then return huge, -huge end
    local lo, hi = -huge, huge
    for i = 1, h do
      -- inside edge i: cross(e, p - P) > 0, linear in s: a s + b > 0
      local a = ex[i] * uy - ey[i] * ux
      local b = ey[i] * px[i] - ex[i] * py[i]
      if a > 0 then
        lo = max(lo, -b / a)
      elseif a < 0 then
        hi = min(hi, -b / a)
      elseif b <= 0 then
        return huge, -huge
      end
    end
    return lo, hi
  end
  local lo, hi = huge, -huge
  local r2 = r * r
  -- open disks at the core's vertices: |s u - P| < r
  for i = 1, h do
    local x, y = px[i], py[i]
    local off = ux * y - uy * x
    local disc = r2 - off * off
    if disc > 0 then
      local mid, half = ux * x + uy * y, sqrt(disc)
      lo, hi = min(lo, mid - half), max(hi, mid + half)
    end
  end
  -- open slabs along the edges: 0 < (s u - P).e < len and |(s u - P).n| < r
  local nx, ny, len = M.nx, M.ny, M.len
  for i = 1, M.m do
    local x, y = px[i], py[i]
    local a0, a1 = -huge, huge
    local along, offA = ux * ex[i] + uy * ey[i], x * ex[i] + y * ey[i]
    if along > 0 then
      a0, a1 = offA / along, (offA + len[i]) / along
    elseif along < 0 then
      a0, a1 = (offA + len[i]) / along, offA / along
    elseif not (offA < 0 and -offA < len[i]) then
      a0, a1 = huge, -huge
    end
    local perp, offB = ux * nx[i] + uy * ny[i], x * nx[i] + y * ny[i]
    if perp > 0 then
      a0, a1 = max(a0, (offB - r) / perp), min(a1, (offB + r) / perp)
    elseif perp < 0 then
      a0, a1 = max(a0, (offB + r) / perp), min(a1, (offB - r) / perp)
    elseif abs(offB) >= r then
      a0, a1 = huge, -huge
    end
    if a0 < a1 then lo, hi = min(lo, a0), max(hi, a1) end
  end
  return lo, hi
end

-- A sampled direction: its angle, unit vector, every M's line interval, and f (capped).
local function sample(Ms, K, theta, cap)
  local ux, uy = cos(theta), sin(theta)
  local lo, hi = {}, {}
  for k = 1, K do lo[k], hi[k] = lineInterval(Ms[k], ux, uy) end
  -- chain the intervals covering s, from s = 0 (each M is used at most once)
  local s = 0
  while s < cap do
    local nxt = s
    for k = 1, K do
      if lo[k] < s and hi[k] > nxt then nxt = hi[k] end
    end
    if nxt == s then break end
    s = nxt
  end
  return { theta = theta, ux = ux, uy = uy, lo = lo, hi = hi, f = s }
end

--- f(u) for the direction at angle `theta`: the smallest s >= 0 with s u outside every
--- int(Mij) of `Ms` (a list from oracle.differences), exact per direction.
function oracle.exit(Ms, theta)
  return sample(Ms, #Ms, theta, huge).f
end

-- Lower bound of f over the sector between directions D1 and D2 with middle Dm (see the
-- header), capped at `cap`.
local function lowerBound(K, D1, D2, Dm, cap)
  local c = cos((D2.theta - D1.theta) / 2)
  local lo1, hi1, lo2, hi2, him = D1.lo, D1.hi, D2.lo, D2.hi, Dm.hi
  local s = 0
  while s < cap do
    local nxt = s
    for k = 1, K do
      if lo1[k] < s and s < hi1[k] and lo2[k] < s and s < hi2[k] then
        local cand = min(hi1[k], hi2[k], c * him[k])
        if cand > nxt then nxt = cand end
      end
    end
    if nxt == s then break end
    s = nxt
  end
  return s
end

--- The minimal separating translation of b (members B) from a (members A).
--- Returns tx, ty, length, info when the origin is strictly inside some Mij; else nil,
--- margin (the distance from the origin to the union, >= 0). info = { margin = minus the
--- depth of the origin in its deepest Mij, unresolved = the largest gap between U and a
--- lower bound left on an interval too narrow to split (0 normally), samples = count }.
function oracle.solve(A, B)
  local all = oracle.differences(A, B)
  local margin = huge
  for k = 1, #all do
    all[k].d0 = distance(all[k], 0, 0)
    margin = min(margin, all[k].d0)
  end
  if margin >= 0 then return nil, margin end
  -- A first upper bound from four directions, then only the Ms nearer than it matter:
  -- a point s u with s < U is nearer than U.
  local U, best = huge, nil
  for q = 0, 3 do
    local D = sample(all, #all, q * pi / 2, huge)
    if D.f < U then U, best = D.f, D end
  end
  local Ms = {}
  for k = 1, #all do
    if all[k].d0 < U then Ms[#Ms + 1] = all[k] end
  end
  local K = #Ms
  local samples = 4
  local function take(theta)
    local D = sample(Ms, K, theta, U)
    samples = samples + 1
    if D.f < U then U, best = D.f, D end
    return D
  end
  local ends = {}
  for i = 0, START - 1 do ends[i] = take(2 * pi * i / START) end
  local work = {}
  for i = 1, START do
    local t1, t2 = 2 * pi * (i - 1) / START, 2 * pi * i / START
    -- (the last interval ends where the first starts, at angle 2 pi rather than 0)
    local D2 = ends[i] or { theta = t2, lo = ends[0].lo, hi = ends[0].hi, f = ends[0].f }
    work[#work + 1] = { ends[i - 1], D2, take((t1 + t2) / 2) }
  end
  local unresolved = 0
  while #work > 0 do
    local nextWork = {}
    for w = 1, #work do
      local D1, D2, Dm = work[w][1], work[w][2], work[w][3]
      local lb = lowerBound(K, D1, D2, Dm, U)
      if lb < U * (1 - REL) then
        if D2.theta - D1.theta < MIN_WIDTH then
          unresolved = max(unresolved, U - lb)
        else
          nextWork[#nextWork + 1] = { D1, Dm, take((D1.theta + Dm.theta) / 2) }
          nextWork[#nextWork + 1] = { Dm, D2, take((Dm.theta + D2.theta) / 2) }
        end
      end
    end
    work = nextWork
  end
  return U * best.ux, U * best.uy, U, { margin = margin, unresolved = unresolved, samples = samples }
end

--- Does any member pair still overlap after b moves by (tx, ty)? True when t is deeper
--- than `tol` inside some Mij (a signed distance from t to its core, against its radius);
--- second result: the largest such depth (<= tol when false).
function oracle.overlaps(A, B, tx, ty, tol)
  local deepest = -huge
  for i = 1, #A do
    for j = 1, #B do
      local depth = -distance(difference(A[i], B[j]), tx, ty)
      if depth > deepest then deepest = depth end
    end
  end
  return deepest > (tol or 0), deepest
end

--- A length scale for tolerances: the largest coordinate magnitude plus radius of any
--- member (at least 1).
function oracle.scale(A, B)
  local s = 1
  for _, list in ipairs({ A, B }) do
    for i = 1, #list do
      local m = list[i]
      for k = 1, m.n do s = max(s, abs(m.xs[k]) + (m.r or 0), abs(m.ys[k]) + (m.r or 0)) end
    end
  end
  return s
end

--- The members of a strike body (a collider or a bare shape), read through public
--- accessors only: a circle is its centre and radius; anything else its core vertices
--- (getVertices) and its rounding (getRounding, when shapes have it; else 0).
function oracle.members(body)
  local list = {}
  local function add(s)
    if s:getKind() == 'circle' then
      local x, y = s:getCentroid()
      list[#list + 1] = { xs = { x }, ys = { y }, n = 1, r = s:getRadius() }
    else
      local v, n = s:getVertices()
      n = n or #v / 2
      local xs, ys = {}, {}
      for i = 1, n do xs[i], ys[i] = v[2 * i - 1], v[2 * i] end
      list[#list + 1] = { xs = xs, ys = ys, n = n, r = s.getRounding and s:getRounding() or 0 }
    end
  end
  if body.elems then
    for s in body:elems() do add(s) end
  else
    add(body)
  end
  return list
end

return oracle
