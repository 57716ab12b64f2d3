--- An independent geometry oracle for the property specs.
---
--- It reads shapes only through their public accessors (getVertices, getCentroid,
--- getRadius, getVertexCount) and never calls strike's SAT, normals, containment or hull
--- code: windings, hulls, clipping and distances are all recomputed here from scratch.
---
--- A shape becomes a plain description:
---   { circle = true, x = , y = , r = }                 a circle
---   { xs = {...}, ys = {...}, n = n }                  a polygon (n >= 3, positive winding)
---                                                      or a segment (n == 2)
---
--- Two independent views of a pair:
---  * brute.overlaps(a, b): do the open interiors intersect? Decided geometrically:
---      polygon-polygon: area of the Sutherland-Hodgman clip of one by the other > 0
---        (robust where "a vertex strictly inside, or two edges properly crossing" misses
---        overlaps whose vertices all sit on the other's edges);
---      segment-polygon: some open sub-interval of the segment lies strictly inside;
---      segment-segment: a proper crossing (both orientation tests strictly opposite);
---      circle-polygon: centre strictly inside, or distance centre-to-boundary < r;
---      circle-segment: distance centre-to-segment < r; circle-circle: centre distance.
---  * brute.signedDistance(a, b): minus the penetration depth when overlapping, else the
---    gap, from the Minkowski difference A - B = hull{a_i - b_j} (offset by the radii of
---    circles): the signed distance from the origin to its boundary. Also returns the
---    runner-up face distance (for detecting ties of the minimum translation).
local brute = {}

local sqrt, huge, abs = math.sqrt, math.huge, math.abs

-- Cross product of (a - o) and (b - o).
local function cross(ox, oy, ax, ay, bx, by)
  return (ax - ox) * (by - oy) - (ay - oy) * (bx - ox)
end
brute.cross = cross

--- Signed shoelace area of the polygon xs, ys (count n), taken about the first vertex so
--- that small polygons far from the origin keep their precision.
function brute.shoelace(xs, ys, n)
  local ox, oy = xs[1], ys[1]
  local s = 0
  for i = 2, n - 1 do
    s = s + (xs[i] - ox) * (ys[i + 1] - oy) - (xs[i + 1] - ox) * (ys[i] - oy)
  end
  return s / 2
end

--- Signed shoelace area of a flat list {x1, y1, x2, y2, ...}.
function brute.shoelaceFlat(v)
  local xs, ys, n = {}, {}, #v / 2
  for i = 1, n do xs[i], ys[i] = v[2 * i - 1], v[2 * i] end
  return brute.shoelace(xs, ys, n)
end

--- The plain description of a strike shape (see the header).
function brute.of(shape)
  if shape:getVertexCount() == 0 then
    local x, y = shape:getCentroid()
    return { circle = true, x = x, y = y, r = shape:getRadius() }
  end
  local v, n = shape:getVertices()
  local xs, ys = {}, {}
  for i = 1, n do xs[i], ys[i] = v[2 * i - 1], v[2 * i] end
  if n >= 3 and brute.shoelace(xs, ys, n) < 0 then
    for i = 1, math.floor(n / 2) do
      local j = n + 1 - i
      xs[i], xs[j] = xs[j], xs[i]
      ys[i], ys[j] = ys[j], ys[i]
    end
  end
  return { xs = xs, ys = ys, n = n }
end

--- Distance from (px, py) to the segment (x1, y1)-(x2, y2).
local function pointSegDist(px, py, x1, y1, x2, y2)
  local ex, ey = x2 - x1, y2 - y1
  local l2 = ex * ex + ey * ey
  local t = 0
  if l2 > 0 then
    t = ((px - x1) * ex + (py - y1) * ey) / l2
    if t < 0 then t = 0 elseif t > 1 then t = 1 end
  end
  local dx, dy = px - (x1 + t * ex), py - (y1 + t * ey)
  return sqrt(dx * dx + dy * dy)
end
brute.pointSegDist = pointSegDist

--- True when (x, y) is strictly inside the convex polygon P (positive winding, n >= 3).
local function insideConvex(P, x, y)
  local xs, ys, n = P.xs, P.ys, P.n
  if n < 3 then return false end
  for i = 1, n do
    local j = i < n and i + 1 or 1
    if cross(xs[i], ys[i], xs[j], ys[j], x, y) <= 0 then return false end
  end
  return true
end
brute.insideConvex = insideConvex

--- Distance from (x, y) to the boundary of P (a polygon or a segment).
local function boundaryDist(P, x, y)
  local xs, ys, n = P.xs, P.ys, P.n
  local d = huge
  local m = n == 2 and 1 or n
  for i = 1, m do
    local j = i < n and i + 1 or 1
    local e = pointSegDist(x, y, xs[i], ys[i], xs[j], ys[j])
    if e < d then d = e end
  end
  return d
end
brute.boundaryDist = boundaryDist

--- Signed distance from (x, y) to P: negative inside (minus the distance to the
--- boundary), positive outside; a segment has no inside.
function brute.pointSignedDist(P, x, y)
  local d = boundaryDist(P, x, y)
  if insideConvex(P, x, y) then return -d end
  return d
end

-- Proper crossing of segments p1-p2 and q1-q2: each strictly separates the other's ends.
local function properCross(p1x, p1y, p2x, p2y, q1x, q1y, q2x, q2y)
  local o1 = cross(p1x, p1y, p2x, p2y, q1x, q1y)
  local o2 = cross(p1x, p1y, p2x, p2y, q2x, q2y)
  local o3 = cross(q1x, q1y, q2x, q2y, p1x, p1y)
  local o4 = cross(q1x, q1y, q2x, q2y, p2x, p2y)
  return ((o1 > 0 and o2 < 0) or (o1 < 0 and o2 > 0)) and ((o3 > 0 and o4 < 0) or (o3 < 0 and o4 > 0))
end
brute.properCross = properCross

-- Area of (convex polygon A) clipped by every edge line of (convex polygon B).
local function clipArea(A, B)
  local px, py, pn = {}, {}, A.n
  for i = 1, pn do px[i], py[i] = A.xs[i], A.ys[i] end
  local bx, by, bn = B.xs, B.ys, B.n
  for e = 1, bn do
    if pn == 0 then return 0 end
    local f = e < bn and e + 1 or 1
    local x1, y1, x2, y2 = bx[e], by[e], bx[f], by[f]
    local qx, qy, qn = {}, {}, 0
    for i = 1, pn do
      local j = i < pn and i + 1 or 1
      local di = cross(x1, y1, x2, y2, px[i], py[i])
      local dj = cross(x1, y1, x2, y2, px[j], py[j])
      if di >= 0 then
        qn = qn + 1
        qx[qn], qy[qn] = px[i], py[i]
      end
      if (di > 0 and dj < 0) or (di < 0 and dj > 0) then
        local t = di / (di - dj)
        qn = qn + 1
        qx[qn], qy[qn] = px[i] + t * (px[j] - px[i]), py[i] + t * (py[j] - py[i])
      end
    end
    px, py, pn = qx, qy, qn
  end
  if pn < 3 then return 0 end
  return brute.shoelace(px, py, pn)
end
brute.clipArea = clipArea

-- Does some open piece of segment S (n == 2) lie strictly inside convex polygon P?
-- The set of t in [0, 1] where every edge function is > 0 is an intersection of open
-- half-lines with [0, 1]: it is non-empty exactly when lo < hi.
local function segmentInside(S, P)
  local x1, y1, x2, y2 = S.xs[1], S.ys[1], S.xs[2], S.ys[2]
  local xs, ys, n = P.xs, P.ys, P.n
  local lo, hi = 0, 1
  for i = 1, n do
    local j = i < n and i + 1 or 1
    local f0 = cross(xs[i], ys[i], xs[j], ys[j], x1, y1)
    local f1 = cross(xs[i], ys[i], xs[j], ys[j], x2, y2)
    if f0 == f1 then
      if f0 <= 0 then return false end
    else
      local t = -f0 / (f1 - f0)
      if f1 > f0 then
        if t > lo then lo = t end
      elseif t < hi then
        hi = t
      end
    end
  end
  return lo < hi
end

--- Do the open interiors of a and b (descriptions) intersect? (A segment's "interior"
--- is its relative interior; two segments overlap only by crossing properly.)
function brute.overlaps(a, b)
  if a.circle and b.circle then
    local dx, dy = b.x - a.x, b.y - a.y
    return sqrt(dx * dx + dy * dy) < a.r + b.r
  end
  if a.circle or b.circle then
    local C, P = a, b
    if b.circle then C, P = b, a end
    return insideConvex(P, C.x, C.y) or boundaryDist(P, C.x, C.y) < C.r
  end
  if a.n == 2 and b.n == 2 then
    return properCross(a.xs[1], a.ys[1], a.xs[2], a.ys[2], b.xs[1], b.ys[1], b.xs[2], b.ys[2])
  end
  if a.n == 2 then return segmentInside(a, b) end
  if b.n == 2 then return segmentInside(b, a) end
  return clipArea(a, b) > 0
end

-- Convex hull (monotone chain) of points xs, ys, dropping collinear points; positive
-- winding. Returns hx, hy, h (h < 3 when all points are collinear: then the extremes).
local function hull(xs, ys, n)
  local idx = {}
  for i = 1, n do idx[i] = i end
  table.sort(idx, function(p, q)
    if xs[p] ~= xs[q] then return xs[p] < xs[q] end
    return ys[p] < ys[q]
  end)
  local hx, hy, h = {}, {}, 0
  for k = 1, n do
    local i = idx[k]
    while h >= 2 and cross(hx[h - 1], hy[h - 1], hx[h], hy[h], xs[i], ys[i]) <= 0 do h = h - 1 end
    h = h + 1
    hx[h], hy[h] = xs[i], ys[i]
  end
  local lower = h + 1
  for k = n - 1, 1, -1 do
    local i = idx[k]
    while h >= lower and cross(hx[h - 1], hy[h - 1], hx[h], hy[h], xs[i], ys[i]) <= 0 do h = h - 1 end
    h = h + 1
    hx[h], hy[h] = xs[i], ys[i]
  end
  h = h - 1
  if h < 1 then h = 1 end
  return hx, hy, h
end
brute.hull = hull

-- Points of A - B (every vertex difference). A circle contributes its centre.
local function diffPoints(a, b)
  local axs, ays = a.xs or { a.x }, a.ys or { a.y }
  local bxs, bys = b.xs or { b.x }, b.ys or { b.y }
  local xs, ys, n = {}, {}, 0
  for i = 1, #axs do
    for j = 1, #bxs do
      n = n + 1
      xs[n], ys[n] = axs[i] - bxs[j], ays[i] - bys[j]
    end
  end
  return xs, ys, n
end

--- Signed distance between a and b: minus the penetration depth when their interiors
--- overlap, else the gap (0 when touching). Second result: the distance from the origin
--- to the next-nearest face line of the Minkowski difference (huge when there is none,
--- or when separated), to tell a unique minimum translation from a tie.
function brute.signedDistance(a, b)
  local r = (a.r or 0) + (b.r or 0)
  local xs, ys, n = diffPoints(a, b)
  local hx, hy, h = hull(xs, ys, n)
  if h < 3 then
    local d
    if h == 1 then
      d = sqrt(hx[1] * hx[1] + hy[1] * hy[1])
    else
      d = pointSegDist(0, 0, hx[1], hy[1], hx[2], hy[2])
    end
    return d - r, huge
  end
  local inside = true
  for i = 1, h do
    local j = i < h and i + 1 or 1
    if cross(hx[i], hy[i], hx[j], hy[j], 0, 0) <= 0 then inside = false break end
  end
  if not inside then
    local d = huge
    for i = 1, h do
      local j = i < h and i + 1 or 1
      local e = pointSegDist(0, 0, hx[i], hy[i], hx[j], hy[j])
      if e < d then d = e end
    end
    return d - r, huge
  end
  -- inside: distances from the origin to the face lines (the nearest boundary point of a
  -- convex polygon from inside lies on the nearest face line)
  local d1, d2 = huge, huge
  for i = 1, h do
    local j = i < h and i + 1 or 1
    local ex, ey = hx[j] - hx[i], hy[j] - hy[i]
    local e = cross(hx[i], hy[i], hx[j], hy[j], 0, 0) / sqrt(ex * ex + ey * ey)
    if e < d1 then d1, d2 = e, d1 elseif e < d2 then d2 = e end
  end
  return -d1 - r, d2 == huge and huge or -d2 - r
end

--- A length scale for tolerances: the largest coordinate magnitude plus size involved.
function brute.scale(a, b)
  local s = 1
  for _, d in ipairs({ a, b }) do
    if d.circle then
      s = math.max(s, abs(d.x) + d.r, abs(d.y) + d.r)
    else
      for i = 1, d.n do s = math.max(s, abs(d.xs[i]), abs(d.ys[i])) end
    end
  end
  return s
end

--- Is (x, y) strictly inside the simple polygon xs, ys (count n)? Crossing-number test.
function brute.insideSimple(xs, ys, n, x, y)
  local inside = false
  for i = 1, n do
    local j = i < n and i + 1 or 1
    local yi, yj = ys[i], ys[j]
    if (yi > y) ~= (yj > y) then
      local xc = xs[i] + (y - yi) / (yj - yi) * (xs[j] - xs[i])
      if x < xc then inside = not inside end
    end
  end
  return inside
end

--- Distance from (x, y) to the outline xs, ys (count n, closed).
function brute.outlineDist(xs, ys, n, x, y)
  local d = huge
  for i = 1, n do
    local j = i < n and i + 1 or 1
    local e = pointSegDist(x, y, xs[i], ys[i], xs[j], ys[j])
    if e < d then d = e end
  end
  return d
end

return brute
