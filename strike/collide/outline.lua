--- The outline rule: the MTV between two compound bodies is the shortest translation of
--- the second that separates all of its members from all of the first's, not the deepest
--- member pair's (which can point through a seam between members, into a neighbour).
---
--- Members a (of the first body) and b (of the second) overlap after b moves by t exactly
--- when t is inside M = a - b, their Minkowski difference: the difference of their cores
--- (polygon, segment or point) grown by the sum of their radii (collide/rounded.lua). The
--- answer is the point nearest the origin outside the union F of those differences. That
--- point lies on the boundary of F, which is made of pieces of the differences' features
--- (their faces moved out by the radius, and circles about their vertices); restricted to
--- one feature, the nearest point of a free stretch is the feature's own nearest point,
--- one of its ends, or a point where another difference's boundary crosses it. So the
--- answer is the nearest free point among: each feature's nearest point and ends, and
--- every crossing of two features of different differences. (Penetration depth of bodies
--- cut into convex pieces as the distance from the origin to the boundary of the union of
--- the pieces' pairwise Minkowski sums is the formulation of Y. J. Kim, M. C. Lin and
--- D. Manocha, "Fast penetration depth computation using rasterization hardware and
--- hierarchical refinement", 2002, who approximate it on graphics hardware; the exact
--- enumeration of candidates here follows from the argument above.) Ties go to the first
--- candidate found, in member order: the answer depends on nothing but the bodies.
---
--- Free means: not inside any difference (by more than round-off), and not on a seam: a
--- candidate on one difference's boundary is moved a hair outward (along the feature's
--- normal, or between both normals at a crossing), and if that lands inside the difference
--- of a member that has seams (the pieces of a Concave outline, whose shared edges are not
--- surfaces), the candidate is inside the outline, not on it. (Members without seams that
--- merely touch are separate solids: a body squeezed exactly between them touches both and
--- overlaps neither, which is free. That only matters for bodies with no thickness across
--- the touching faces, such as points.)
---
--- Cost. The deepest pair's own MTV is tried first: its length is a lower bound (every
--- overlapping pair must be left), so when it is free it is the answer (the usual case: a
--- body on a flat floor of tiles, or in one piece of an outline). Otherwise only pairs whose
--- bounds are nearer than an answer already known (at worst, lifting the second body's
--- bounds clear of the first's) take part, and only features that pass through the ring
--- between that lower bound and the best answer so far. Everything lives in module-level
--- scratch arrays: nothing is allocated per call once they have grown.
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local layout = require(ROOT .. '.base.layout')
local COUNT = layout.COUNT

local sqrt, huge, abs = math.sqrt, math.huge, math.abs
local X, Y, R = layout.X, layout.Y, layout.R
local MINX, MINY, MAXX, MAXY = layout.MINX, layout.MINY, layout.MAXX, layout.MAXY
local STRIDE, VY, NX, NY, BASE = layout.STRIDE, layout.VY, layout.NX, layout.NY, layout.BASE

local outline = {}

--- Relative tolerance: a candidate inside a difference by less than TOL times the scene's
--- size counts as free (round-off).
outline.TOL = 1e-11
--- The outward step of the seam test, relative to the scene's size.
outline.NUDGE = 1e-9

-- The differences: difference m has core vertices first[m] .. first[m] + count[m] - 1 in
-- vx, vy (positive winding), with the outward normal (nx, ny) and offset d of the edge from
-- each vertex to the next; radius rad[m]; the members memberA[m], memberB[m]. Each vertex k
-- is the sum of vertex va[k] of a's core and the negated vertex vb[k] of b's (1 for a circle),
-- and the edge from it is a's face esrc[k] (> 0), b's face -esrc[k] (< 0; when the two are
-- parallel, a's), or none (0: a difference of two points).
local first, count, rad, memberA, memberB = {}, {}, {}, {}, {}
local vx, vy, enx, eny, ed, va, vb, esrc = {}, {}, {}, {}, {}, {}, {}, {}
local nDiff, nVert = 0, 0

-- A member's core, as the merge below reads it: its vertex count (a circle's is its centre,
-- 1; a capsule of zero length, whose two vertices coincide, is one point too), a vertex,
-- and the outward normal of the edge from vertex i to the next.
local function coreCount(s)
  local n = s[COUNT]
  if not n then return 1 end
  if n == 2 and s[STRIDE + BASE] == s[2 * STRIDE + BASE] and s[STRIDE + BASE + VY] == s[2 * STRIDE + BASE + VY] then
    return 1
  end
  return n
end
local function coreVertex(s, i)
  if s[COUNT] then
    local k = STRIDE * i + BASE
    return s[k], s[k + VY]
  end
  return s[X], s[Y]
end

-- The two cores being merged, copied out: vertices and outward edge normals (b's turned
-- half round: negated), counts; and each one's lowest vertex (least y, then least x).
local coreAX, coreAY, coreANX, coreANY, coreBX, coreBY, coreBNX, coreBNY = {}, {}, {}, {}, {}, {}, {}, {}

local function copyCore(s, sign, xs, ys, nxs, nys)
  local n = coreCount(s)
  local lo, lx, ly = 1, huge, huge
  if n == 1 then
    local x, y = coreVertex(s, 1)
    xs[1], ys[1], nxs[1], nys[1] = sign * x, sign * y, 0, 0
    return 1, 1
  end
  for i = 1, n do
    local k = STRIDE * i + BASE
    local x, y = sign * s[k], sign * s[k + VY]
    xs[i], ys[i], nxs[i], nys[i] = x, y, sign * s[k + NX], sign * s[k + NY]
    if y < ly or (y == ly and x < lx) then lo, lx, ly = i, x, y end
  end
  return n, lo
end

-- Add the difference of members a and b (refreshed): the Minkowski sum of a's core and b's
-- turned half round, by merging their edges in the order of their directions from each
-- one's lowest vertex (the classic O(n + m) merge of convex polygons, e.g. M. de Berg et
-- al., Computational Geometry, 3rd ed., 13.3). Each edge of the sum is an edge of one of
-- them and keeps that shape's own unit normal (a's, or b's negated), never one computed
-- from a short difference of nearby points.
local function addDifference(a, b)
  local ax, ay, anx, any = coreAX, coreAY, coreANX, coreANY
  local bx, by, bnx, bny = coreBX, coreBY, coreBNX, coreBNY
  local na, ia = copyCore(a, 1, ax, ay, anx, any)
  local nb, ib = copyCore(b, -1, bx, by, bnx, bny)
  nDiff = nDiff + 1
  local m = nDiff
  first[m], rad[m], memberA[m], memberB[m] = nVert + 1, a[R] + b[R], a, b
  local ea, eb = na > 1 and na or 0, nb > 1 and nb or 0 -- (edges: a point has none)
  local i, j = 0, 0
  repeat
    local pa = (ia + i - 1) % na + 1
    local pb = (ib + j - 1) % nb + 1
    local x, y = ax[pa] + bx[pb], ay[pa] + by[pb]
    nVert = nVert + 1
    vx[nVert], vy[nVert], va[nVert], vb[nVert] = x, y, pa, pb
    -- the next edge: a's edge pa, b's (turned) edge pb, or both when parallel
    local stepA, stepB = i < ea, j < eb
    if stepA and stepB then
      local qa, qb = pa % na + 1, pb % nb + 1
      local c = (ax[qa] - ax[pa]) * (by[qb] - by[pb]) - (ay[qa] - ay[pa]) * (bx[qb] - bx[pb])
      if c > 0 then stepB = false elseif c < 0 then stepA = false end
    end
    local nx, ny, src = 0, 0, 0 -- (two points: no edge)
    if stepA then
      nx, ny, src = anx[pa], any[pa], pa
      i = i + 1
      if stepB then j = j + 1 end
    elseif stepB then
      nx, ny, src = bnx[pb], bny[pb], -pb
      j = j + 1
    end
    enx[nVert], eny[nVert], esrc[nVert] = nx, ny, src
    ed[nVert] = nx * x + ny * y
  until i >= ea and j >= eb
  count[m] = nVert - first[m] + 1
end

-- Signed distance from (x, y) to the core of difference m: negative inside a polygon.
local function coreDistance(m, x, y)
  local f, h = first[m], count[m]
  if h >= 3 then
    local s = -huge
    for k = f, f + h - 1 do
      local d = enx[k] * x + eny[k] * y - ed[k]
      if d > s then s = d end
    end
    if s <= 0 then return s end
  end
  local best = huge
  for k = f, f + h - 1 do
    local l = k < f + h - 1 and k + 1 or f
    local x1, y1 = vx[k], vy[k]
    local ex, ey = vx[l] - x1, vy[l] - y1
    local dx, dy = x - x1, y - y1
    local t = dx * ex + dy * ey
    if t > 0 then
      local e2 = ex * ex + ey * ey
      if t >= e2 then
        dx, dy = x - vx[l], y - vy[l]
      else
        t = t / e2
        dx, dy = dx - t * ex, dy - t * ey
      end
    end
    local d2 = dx * dx + dy * dy
    if d2 < best then best = d2 end
  end
  return sqrt(best)
end

-- Is (x, y) inside some difference by more than tol, skipping difference `skip`?
local function covered(x, y, tol, skip)
  for m = 1, nDiff do
    if m ~= skip and coreDistance(m, x, y) < rad[m] - tol then return true end
  end
  return false
end

-- The same, over the differences with a member that has seams (faces that are not
-- surfaces: the pieces of a Concave outline, strike/colliders/Concave.lua).
local function coveredAcrossSeams(x, y, tol, skip)
  for m = 1, nDiff do
    if m ~= skip and (memberA[m]._seams or memberB[m]._seams) and coreDistance(m, x, y) < rad[m] - tol then
      return true
    end
  end
  return false
end

-- The best free candidate so far: its squared length, the point, its difference.
local bestD2, bestX, bestY, bestM = huge, 0, 0, 0
local tolerance, nudge = 0, 0
-- The squared lower bound: every point nearer the origin than the deepest pair's depth is
-- inside that pair's difference (the origin is, that deep), so no candidate there is free.
local lowD2 = 0

-- Consider (x, y), on the boundary of difference m with outward unit direction (ux, uy).
local function consider(x, y, m, ux, uy)
  local d2 = x * x + y * y
  if not (d2 < bestD2) or d2 < lowD2 then return end -- luacheck: ignore 581 (NaN is never better)
  if covered(x, y, tolerance, 0) then return end
  if coveredAcrossSeams(x + ux * nudge, y + uy * nudge, tolerance, m) then return end
  bestD2, bestX, bestY, bestM = d2, x, y, m
end

-- Features: 1 = a face moved out (x1, y1, x2, y2, outward normal), 2 = a circle about a
-- vertex (cx, cy, r). Their nearest distance to the origin, for pruning.
local fType, fM, fA, fB, fC, fD, fNX, fNY, fDist, fFar = {}, {}, {}, {}, {}, {}, {}, {}, {}, {}
-- and their bounds
local fX0, fY0, fX1, fY1 = {}, {}, {}, {}
local nFeat = 0

local function addFeatures(m)
  local f, h, r = first[m], count[m], rad[m]
  if h >= 2 then
    for k = f, f + h - 1 do
      local l = k < f + h - 1 and k + 1 or f
      local nx, ny = enx[k], eny[k]
      if nx ~= 0 or ny ~= 0 then
        nFeat = nFeat + 1
        local i = nFeat
        local x1, y1, x2, y2 = vx[k] + nx * r, vy[k] + ny * r, vx[l] + nx * r, vy[l] + ny * r
        fType[i], fM[i], fA[i], fB[i], fC[i], fD[i], fNX[i], fNY[i] = 1, m, x1, y1, x2, y2, nx, ny
        -- its nearest point to the origin, and its ends
        local ex, ey = x2 - x1, y2 - y1
        local t = -(x1 * ex + y1 * ey)
        local e2 = ex * ex + ey * ey
        local qx, qy = x1, y1
        if t >= e2 then qx, qy = x2, y2 elseif t > 0 then qx, qy = x1 + ex * t / e2, y1 + ey * t / e2 end
        fDist[i] = sqrt(qx * qx + qy * qy)
        local f1, f2 = x1 * x1 + y1 * y1, x2 * x2 + y2 * y2
        fFar[i] = sqrt(f1 > f2 and f1 or f2)
        fX0[i], fX1[i] = x1 < x2 and x1 or x2, x1 < x2 and x2 or x1
        fY0[i], fY1[i] = y1 < y2 and y1 or y2, y1 < y2 and y2 or y1
        local q2 = qx * qx + qy * qy
        if q2 < bestD2 then -- (else no point of the face is nearer than the best)
          if q2 >= lowD2 then consider(qx, qy, m, nx, ny) end
          if f1 < bestD2 and f1 >= lowD2 then consider(x1, y1, m, nx, ny) end
          if f2 < bestD2 and f2 >= lowD2 then consider(x2, y2, m, nx, ny) end
        end
      end
    end
  end
  if r > 0 then
    for k = f, f + h - 1 do
      nFeat = nFeat + 1
      local i = nFeat
      local cx, cy = vx[k], vy[k]
      fType[i], fM[i], fA[i], fB[i], fC[i] = 2, m, cx, cy, r
      local c = sqrt(cx * cx + cy * cy)
      fDist[i] = abs(c - r)
      fFar[i] = c + r
      fX0[i], fY0[i], fX1[i], fY1[i] = cx - r, cy - r, cx + r, cy + r
      local ux, uy = 0, -1 -- (a circle about the origin: every point is as near; pick -y)
      if c > 0 then ux, uy = -cx / c, -cy / c end
      consider(cx + ux * r, cy + uy * r, m, ux, uy)
    end
  end
  -- (a difference of two points has no inside: it covers nothing and has no features)
end

-- The outward direction of feature i at (x, y) (on it).
local function normalAt(i, x, y)
  if fType[i] == 1 then return fNX[i], fNY[i] end
  local dx, dy = x - fA[i], y - fB[i]
  local l = sqrt(dx * dx + dy * dy)
  if l > 0 then return dx / l, dy / l end
  return 0, 0
end

-- Consider a crossing (x, y) of features i and j: moved out between both normals.
local function crossing(i, j, x, y)
  local d2 = x * x + y * y
  if not (d2 < bestD2) or d2 < lowD2 then return end -- luacheck: ignore 581 (NaN is never better)
  local ax, ay = normalAt(i, x, y)
  local bx, by = normalAt(j, x, y)
  local ux, uy = ax + bx, ay + by
  local l = sqrt(ux * ux + uy * uy)
  if l > 0 then ux, uy = ux / l, uy / l end
  if covered(x, y, tolerance, 0) then return end
  -- (moved out, it must be clear of every difference with seams, its own two included)
  if l > 0 and coveredAcrossSeams(x + ux * nudge, y + uy * nudge, tolerance, 0) then return end
  bestD2, bestX, bestY, bestM = d2, x, y, fM[i]
end

-- The crossings of features i and j (of different differences).
local function cross(i, j)
  local ti, tj = fType[i], fType[j]
  if ti == 2 and tj == 1 then i, j, ti, tj = j, i, tj, ti end
  if ti == 1 and tj == 1 then
    local x1, y1, ex, ey = fA[i], fB[i], fC[i] - fA[i], fD[i] - fB[i]
    local x3, y3, gx, gy = fA[j], fB[j], fC[j] - fA[j], fD[j] - fB[j]
    local den = ex * gy - ey * gx
    if den == 0 then return end
    local wx, wy = x3 - x1, y3 - y1
    local s = (wx * gy - wy * gx) / den
    local t = (wx * ey - wy * ex) / den
    if s >= 0 and s <= 1 and t >= 0 and t <= 1 then crossing(i, j, x1 + s * ex, y1 + s * ey) end
  elseif ti == 1 then -- a face and a circle
    local x1, y1, ex, ey = fA[i], fB[i], fC[i] - fA[i], fD[i] - fB[i]
    local cx, cy, r = fA[j], fB[j], fC[j]
    local e2 = ex * ex + ey * ey
    local mx, my = x1 - cx, y1 - cy
    local b = (mx * ex + my * ey) / e2
    local qx, qy = mx - b * ex, my - b * ey -- (the circle's centre to the line's nearest point)
    local disc = (r * r - (qx * qx + qy * qy)) / e2
    if disc < 0 then return end
    local root = sqrt(disc)
    for k = -1, 1, 2 do
      local s = -b + k * root
      if s >= 0 and s <= 1 then crossing(i, j, x1 + s * ex, y1 + s * ey) end
    end
  else -- two circles
    local ax, ay, ra = fA[i], fB[i], fC[i]
    local bx, by, rb = fA[j], fB[j], fC[j]
    local dx, dy = bx - ax, by - ay
    local d2 = dx * dx + dy * dy
    if d2 == 0 then return end
    local d = sqrt(d2)
    local a = (ra * ra - rb * rb + d2) / (2 * d)
    local h2 = ra * ra - a * a
    if h2 < 0 then return end
    local h = sqrt(h2)
    local mx, my = ax + dx * a / d, ay + dy * a / d
    crossing(i, j, mx - dy * h / d, my + dx * h / d)
    crossing(i, j, mx + dy * h / d, my - dx * h / d)
  end
end

-- The bounds of the solid leaves (all but chain segments) of a leaf list.
local function solidBounds(list, n)
  local x0, y0, x1, y1 = huge, huge, -huge, -huge
  for i = 1, n do
    local s = list[i]
    if s._kind ~= 'chain' then
      if s[MINX] < x0 then x0 = s[MINX] end
      if s[MINY] < y0 then y0 = s[MINY] end
      if s[MAXX] > x1 then x1 = s[MAXX] end
      if s[MAXY] > y1 then y1 = s[MAXY] end
    end
  end
  return x0, y0, x1, y1
end

-- Scratch for the pruned feature list.
local near = {}

--- Apply the outline rule to the solid member pairs of the leaf lists l1 (n1 leaves) and l2
--- (n2), given `best`, the deepest pair's MTV (filled by a narrow phase), which is kept
--- when it is free (see the header) and otherwise overwritten with the answer (edgeIndex 0;
--- colliderShape and collidedShape: the members whose difference gave it). Chain segments
--- (kind 'chain') take no part: they are surfaces, not solids. Returns `best`.
---@param best table an MTV-shaped table
---@param l1 strike.Shape[]
---@param n1 integer
---@param l2 strike.Shape[]
---@param n2 integer
---@return table best
function outline.resolve(best, l1, n1, l2, n2)
  -- The scale of round-off: the deepest pair's size and distance from the origin.
  local sa, sb = best.colliderShape, best.collidedShape
  local scale = (sa[MAXX] - sa[MINX]) + (sa[MAXY] - sa[MINY]) + (sb[MAXX] - sb[MINX]) + (sb[MAXY] - sb[MINY])
    + abs(sa[X]) + abs(sa[Y]) + abs(sb[X]) + abs(sb[Y])
  tolerance, nudge = outline.TOL * scale, outline.NUDGE * scale
  -- The deepest pair's MTV, when it is free, is the answer (its length is a lower bound);
  -- a hair further along it must be free too (else it stops on a seam). Only the pairs
  -- whose bounds meet once the second body has moved by it can cover it.
  local tx, ty = best.x, best.y
  local ux, uy = tx + best.nx * nudge, ty + best.ny * nudge
  nDiff, nVert = 0, 0
  local lx, hx = tx < ux and tx or ux, tx < ux and ux or tx -- (the moves' range on each axis)
  local ly, hy = ty < uy and ty or uy, ty < uy and uy or ty
  for j = 1, n2 do
    local b = l2[j]
    if b._kind ~= 'chain' then
      -- b's bounds over both moves, less the tolerance: a member whose bounds do not reach
      -- into them overlaps b by less than that after either move (touching members, such as
      -- the tiles a box has just been lifted onto, need no difference)
      local x0, y0 = b[MINX] + lx + tolerance, b[MINY] + ly + tolerance
      local x1, y1 = b[MAXX] + hx - tolerance, b[MAXY] + hy - tolerance
      for i = 1, n1 do
        local a = l1[i]
        if a[MAXX] > x0 and a[MINX] < x1 and a[MAXY] > y0 and a[MINY] < y1 and a._kind ~= 'chain' then
          addDifference(a, b)
        end
      end
    end
  end
  if not covered(tx, ty, tolerance, 0) and not coveredAcrossSeams(ux, uy, tolerance, 0) then
    for m = 1, nDiff do memberA[m], memberB[m] = false, false end -- (strike keeps no shape alive)
    return best
  end
  -- An answer known free: lift the second body's bounds clear of the first's.
  local ax0, ay0, ax1, ay1 = solidBounds(l1, n1)
  local bx0, by0, bx1, by1 = solidBounds(l2, n2)
  local fx, fy = ax1 - bx0, 0
  if bx1 - ax0 < abs(fx) then fx = -(bx1 - ax0) end
  if ay1 - by0 < abs(fx) + abs(fy) then fx, fy = 0, ay1 - by0 end
  if by1 - ay0 < abs(fx) + abs(fy) then fx, fy = 0, -(by1 - ay0) end
  local reach = abs(fx) + abs(fy)
  -- The differences of the pairs that can matter: bounds nearer than `reach`.
  nDiff, nVert = 0, 0
  for i = 1, n1 do
    local a = l1[i]
    if a._kind ~= 'chain' then
      for j = 1, n2 do
        local b = l2[j]
        if b._kind ~= 'chain' and a[MINX] - b[MAXX] < reach and b[MINX] - a[MAXX] < reach
          and a[MINY] - b[MAXY] < reach and b[MINY] - a[MAXY] < reach then
          addDifference(a, b)
        end
      end
    end
  end
  -- Otherwise the nearest free candidate, starting from the lift (free by construction).
  bestD2, bestX, bestY, bestM = fx * fx + fy * fy, fx, fy, 0
  local low = best.depth - tolerance
  lowD2 = low > 0 and low * low or 0
  nFeat = 0
  for m = 1, nDiff do addFeatures(m) end
  -- (a feature matters only where it passes between the two bounds)
  local k = 0
  for i = 1, nFeat do
    if fDist[i] * fDist[i] < bestD2 and fFar[i] * fFar[i] >= lowD2 then
      k = k + 1
      near[k] = i
    end
  end
  for p = 1, k do
    local i = near[p]
    local m, x0, y0, x1, y1 = fM[i], fX0[i], fY0[i], fX1[i], fY1[i]
    for q = p + 1, k do
      local j = near[q]
      -- (features of two differences, whose bounds meet, and nearer than the best)
      if fM[j] ~= m and fX0[j] <= x1 and x0 <= fX1[j] and fY0[j] <= y1 and y0 <= fY1[j] then
        local limit = sqrt(bestD2)
        if fDist[i] < limit and fDist[j] < limit then cross(i, j) end
      end
    end
  end
  local d = sqrt(bestD2)
  local nx, ny = 0, -1
  if d > 0 then nx, ny = bestX / d, bestY / d end
  best.x, best.y, best.nx, best.ny, best.depth = bestX, bestY, nx, ny, d
  best.separating = false
  best.edgeIndex = 0
  if bestM > 0 then
    best.colliderShape, best.collidedShape = memberA[bestM], memberB[bestM]
  end
  for m = 1, nDiff do memberA[m], memberB[m] = false, false end -- (strike keeps no shape alive)
  return best
end

-- Faces of a and b whose normals are this near (in cosine) are one face to round-off: the
-- difference may hold them as two edges, or as one (exactly parallel), and which of the two
-- the push ends on is round-off's choice. The first body's is taken, as the narrow phase
-- keeps it (collide/sat.lua), so that a pair resting on it keeps its contact ids.
local PARALLEL = 1e-9

--- Where members a and b (solid, refreshed) touch once b has moved by (tx, ty): nothing
--- (nil) unless they touch after the move (the difference's boundary within `tol` of t) and
--- their depth along the normal below is more than `minDepth` (a pair the move only slid
--- along, or brought b to from beside it, is touching, not colliding). Otherwise the pair's
--- own unit normal (from a toward b) and the feature it touches along:
---   face > 0: face `face` of a;  face < 0: face -face of b (its normal turned);
---   face 0: a rounded corner or a circle: core vertex ia of a against core vertex ib of b
---   (1 for a circle's centre), the normal along the line between them (after the move).
--- A face is one whose segment (moved out by the radii) passes within `tol` of t; when several
--- do (at a sharp corner of the difference: a vertex touching a vertex), the one most aligned
--- with the push's direction (ux, uy), the first found when tied; and when it is b's and a's
--- face beside it in the difference is parallel to it (within PARALLEL) with its line within
--- `tol` of t, a's. The pair's depth, how far its projections on that normal overlap before
--- the move, is normal . t (the difference's support along its own normal at t), returned
--- third.
---@param a strike.Shape
---@param b strike.Shape
---@param tx number
---@param ty number
---@param ux number
---@param uy number
---@param tol number
---@param minDepth number
---@return number|nil nx
---@return number ny
---@return number depth
---@return integer face
---@return integer ia
---@return integer ib
function outline.feature(a, b, tx, ty, ux, uy, tol, minDepth)
  if not (a[MAXX] - b[MINX] - tx >= -tol and b[MAXX] + tx - a[MINX] >= -tol
      and a[MAXY] - b[MINY] - ty >= -tol and b[MAXY] + ty - a[MINY] >= -tol) then
    return nil, 0, 0, 0, 0, 0
  end
  nDiff, nVert = 0, 0
  addDifference(a, b)
  memberA[1], memberB[1] = false, false -- (strike keeps no shape alive)
  local r = rad[1]
  local gap = coreDistance(1, tx, ty) - r
  if not (gap <= tol and gap >= -tol) then return nil, 0, 0, 0, 0, 0 end -- (NaN: no)
  local f, last = first[1], first[1] + count[1] - 1
  local best, score, tol2 = 0, -huge, tol * tol
  for k = f, last do
    local nx, ny = enx[k], eny[k]
    if nx ~= 0 or ny ~= 0 then
      local l = k < last and k + 1 or f
      local ex, ey = vx[l] - vx[k], vy[l] - vy[k]
      local dx, dy = tx - vx[k] - nx * r, ty - vy[k] - ny * r -- (from the face's start, moved out)
      local s = dx * ex + dy * ey
      if s > 0 then
        local e2 = ex * ex + ey * ey
        if s >= e2 then
          dx, dy = dx - ex, dy - ey
        else
          s = s / e2
          dx, dy = dx - s * ex, dy - s * ey
        end
      end
      if dx * dx + dy * dy <= tol2 then
        local c = nx * ux + ny * uy
        if c > score then best, score = k, c end
      end
    end
  end
  if best > 0 and esrc[best] < 0 then -- (b's face: a's beside it, when one to round-off)
    local nx, ny = enx[best], eny[best]
    for side = best - 1, best + 1, 2 do
      local q = side < f and last or side > last and f or side -- (the edges wrap)
      if esrc[q] > 0 and enx[q] * nx + eny[q] * ny >= 1 - PARALLEL then
        local off = enx[q] * tx + eny[q] * ty - ed[q] - r
        if off <= tol and off >= -tol then
          best = q
          break
        end
      end
    end
  end
  if best > 0 then
    local nx, ny = enx[best], eny[best]
    local depth = nx * tx + ny * ty
    if not (depth > minDepth) then return nil, 0, 0, 0, 0, 0 end -- luacheck: ignore 581 (NaN: none)
    return nx, ny, depth, esrc[best], 0, 0
  end
  -- no face: t is on the arc about the nearest core vertex
  local near2, k = huge, f
  for q = f, last do
    local dx, dy = tx - vx[q], ty - vy[q]
    local d2 = dx * dx + dy * dy
    if d2 < near2 then near2, k = d2, q end
  end
  local d = sqrt(near2)
  local nx, ny = ux, uy -- (t on the vertex itself: only a radius of 0 could, and it has faces)
  if d > 0 then nx, ny = (tx - vx[k]) / d, (ty - vy[k]) / d end
  local depth = nx * tx + ny * ty
  if not (depth > minDepth) then return nil, 0, 0, 0, 0, 0 end -- luacheck: ignore 581 (NaN: none)
  return nx, ny, depth, 0, va[k], vb[k]
end

-- LuaJIT: the search runs interpreted. Its short loops with data-dependent trip counts (a
-- difference's few faces, the few differences) make the trace compiler abort again and
-- again ("loop unroll limit reached"); on the compound row of make bench the search ran at
-- 41-43k pairs/s and left 0.34-0.45 KB of garbage per call (aborted traces) compiled, at
-- 73-80k pairs/s with nothing left interpreted. The fast path, and everything it calls,
-- stays compiled (a trace that calls a function the JIT may not compile stops there: with
-- coveredAcrossSeams among these, a box on a floor of tiles ran at 2.6M calls/s, not 3.2M).
local jit = rawget(_G, 'jit')
if jit then
  for _, f in ipairs({ addFeatures, consider, crossing, cross }) do jit.off(f) end
end

return outline
