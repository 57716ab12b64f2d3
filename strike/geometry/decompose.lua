--- Convex decomposition of simple polygons.
--
-- The outline is cleaned (duplicate and collinear points dropped), validated (at least three
-- distinct points, nonzero area, no self-intersection, no spike folding back onto itself),
-- triangulated, and the triangles are merged back into convex pieces with the Hertel-Mehlhorn
-- rule: a diagonal is removed when the union of the two pieces it separates is still convex.
-- Every step takes O(n log n) time for n vertices.
--
-- Sources (the algorithms, written here from their descriptions):
--   * self-intersection: M. I. Shamos and D. Hoey, "Geometric intersection problems", FOCS 1976
--     -- a sweep in which only segments that become neighbours along the sweep line need to be
--     tested (see crossingSweep for the tolerance);
--   * the sweep's ordered set: W. Pugh, "Skip lists: a probabilistic alternative to balanced
--     trees", Comm. ACM 33 (1990);
--   * triangulation: partition into monotone pieces by a plane sweep, then each piece with a
--     stack, as in M. de Berg, O. Cheong, M. van Kreveld and M. Overmars, "Computational
--     Geometry: Algorithms and Applications", 3rd ed., chapter 3 (after D. T. Lee and
--     F. P. Preparata 1977, and M. R. Garey, D. S. Johnson, F. P. Preparata and R. E. Tarjan,
--     "Triangulating a simple polygon", IPL 7, 1978); the sweep runs along x here, ties
--     broken by y;
--   * merging: S. Hertel and K. Mehlhorn, "Fast triangulation of simple polygons", FCT 1983,
--     LNCS 158 -- the result has at most 2r + 1 pieces for r reflex vertices, hence at most
--     four times the optimum. Diagonals are removed greedily, the one leaving the sharpest
--     (most convex) corners first (a binary heap; removing a diagonal only changes the scores
--     of the four diagonals beside it); this gives the optimal count on L, U and comb shapes,
--     where removing them in plain order can leave an extra piece.
--
-- Numerics. The working copy of the outline is scaled by a power of two (exact) so that its
-- extent lies in [0.5, 1]; every tolerance below is therefore relative to the outline's size:
--   * DIST_EPS (1e-12 of the extent): two points closer than this are the same point; a vertex
--     closer than this to a non-adjacent edge touches it.
--   * TURN_EPS (1e-12): three points a, b, c are collinear when
--     |cross(b - a, c - b)| <= TURN_EPS * |b - a| * |c - b|, i.e. the turn at b is below
--     about 1e-12 radians. Convex means a turn above that, strictly.
--   * GAP_EPS (1e-14): the sweeps call a point above or below a segment when their gap along
--     y exceeds this -- far above the rounding of that gap (about 1e-16 here), far below
--     DIST_EPS, so that a point closer than this to a segment always touches it.
-- The triangulation's decisions (sweep order, vertex kinds, which edge lies below a vertex)
-- are exact comparisons or orientation tests with these margins, so its diagonals are the
-- ones exact arithmetic would give. The pieces are made of the caller's own coordinates (never
-- recomputed points), so a piece vertex is always exactly an input vertex.
local ROOT = (...):match('^(.-)%.geometry%.[^%.]+$')
local hull = require(ROOT .. '.geometry.hull')

local decompose = {}

-- LuaJIT runs this file in its interpreter (jit.off, for this chunk and every function in
-- it). A decomposition runs once per outline and takes a different path at nearly every
-- branch: compiled, it made more traces than it saved time. 200 random 32-vertex stars
-- built in a fresh process took 567 ms and 6,566 traces, flushing the trace cache 10 times,
-- under the standalone interpreter's limits (182 ms and 1,394 traces under LÖVE's);
-- interpreted, 206 ms and 611 traces (166 ms under LÖVE's); 200 of 8 vertices 116 -> 64 ms
-- (67 -> 43 under LÖVE's). make bench's outlines (three runs each, ms): 1,000-vertex
-- random star 69-98 -> 25-32, at 10,000 vertices random star 348-421 -> 239-366, regular
-- star 196-305 -> 189-272, comb 113-149 -> 130-173. And a level's outlines no longer flush a
-- game's compiled code out of the trace cache. The constructors its pieces go to
-- (ConvexPolygon) are compiled as usual.
local jit = rawget(_G, 'jit')
if jit then jit.off(true, true) end

local abs, sqrt, floor, max = math.abs, math.sqrt, math.floor, math.max
local HUGE = math.huge

local DIST_EPS = 1e-12
local DIST_EPS2 = DIST_EPS * DIST_EPS
local TURN_EPS = 1e-12
local GAP_EPS = 1e-14
-- Cell size of the close-vertex grid: a power of two (so that cell numbers are exact) above
-- 4 * DIST_EPS, the widest gap closeVertices looks for.
local CELL = 2 ^ -36

local DEGENERATE_TRI = 'could not triangulate outline (numerical degeneracy)'
local DEGENERATE_MERGE = 'could not decompose outline (numerical degeneracy)'

--- Number of distinct (x, y) pairs among the first n points.
local function countDistinct(xs, ys, n)
  local seen, count = {}, 0
  for i = 1, n do
    local x, y = xs[i], ys[i]
    if x == 0 then x = 0 end -- -0.0 and 0.0 are the same point
    if y == 0 then y = 0 end
    local row = seen[x]
    if not row then
      row = {}
      seen[x] = row
    end
    if not row[y] then
      row[y] = true
      count = count + 1
    end
  end
  return count
end

--- cross(b - a, c - b), |b - a| * |c - b| and dot(b - a, c - b) for the corner a -> b -> c.
local function corner(X, Y, a, b, c)
  local ux, uy = X[b] - X[a], Y[b] - Y[a]
  local vx, vy = X[c] - X[b], Y[c] - Y[b]
  return ux * vy - uy * vx, sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy)), ux * vx + uy * vy
end

--- Is vertex b of a -> b -> c strictly convex (a left turn above TURN_EPS)?
local function convex(X, Y, a, b, c)
  local cr, len = corner(X, Y, a, b, c)
  return cr > TURN_EPS * len
end

--- Squared distance from (px, py) to the segment (ax, ay)-(bx, by) of nonzero length.
local function segDist2(px, py, ax, ay, bx, by)
  local ex, ey = bx - ax, by - ay
  px, py = px - ax, py - ay
  local t = (px * ex + py * ey) / (ex * ex + ey * ey)
  if t < 0 then t = 0 elseif t > 1 then t = 1 end
  local dx, dy = px - t * ex, py - t * ey
  return dx * dx + dy * dy
end

--- Do the segments a-b and c-d (no shared endpoint, nonzero lengths) cross or come within
--- DIST_EPS? Their boxes apart by more than the tolerance: no; each one's ends strictly on
--- both sides of the other's line: yes; otherwise the distance of an end to the other
--- segment decides. Written with branches, not math.min and math.max (C calls on Lua
--- 5.1-5.4), and with one early answer: when both ends of c-d lie on one side of a-b's line,
--- farther than 2 * DIST_EPS from it (c1 is that distance times |a-b|), all four distances
--- exceed DIST_EPS by far more than their rounding (about 1e-16 in the working coordinates),
--- so that the distances would say false. Most pairs the sweeps test are such near
--- neighbours (the spikes of a star): the decomposition of a 10,000-vertex random star runs
--- 14% fewer instructions on Lua 5.2 than with the calls and without that answer. (LuaJIT
--- used a branch-free form of the same test while it compiled this file: the same answers,
--- 3.6 million pairs at the tolerance's edges compared on every VM; interpreted, this one is
--- faster there too: 2 million pairs placed near the tolerance give the same answers.)
local function segmentsMeet(X, Y, a, b, c, d)
  local ax, ay, bx, by, cx, cy, dx, dy = X[a], Y[a], X[b], Y[b], X[c], Y[c], X[d], Y[d]
  -- bounding boxes apart by more than the tolerance
  local lo1, hi1, lo2, hi2 = ax, bx, cx, dx
  if bx < ax then lo1, hi1 = bx, ax end
  if dx < cx then lo2, hi2 = dx, cx end
  if lo2 - hi1 > DIST_EPS or lo1 - hi2 > DIST_EPS then return false end
  lo1, hi1, lo2, hi2 = ay, by, cy, dy
  if by < ay then lo1, hi1 = by, ay end
  if dy < cy then lo2, hi2 = dy, cy end
  if lo2 - hi1 > DIST_EPS or lo1 - hi2 > DIST_EPS then return false end
  -- proper crossing: each segment's ends strictly on both sides of the other's line (a
  -- product underflowing to 0 means an end within 1e-150 of the other line: the distances
  -- below see it)
  local ex, ey, fx, fy = bx - ax, by - ay, dx - cx, dy - cy
  local c1 = ex * (cy - ay) - ey * (cx - ax)
  local c2 = ex * (dy - ay) - ey * (dx - ax)
  local c3 = fx * (ay - cy) - fy * (ax - cx)
  local c4 = fx * (by - cy) - fy * (bx - cx)
  if c1 * c2 < 0 and c3 * c4 < 0 then return true end
  -- c-d on one side of a-b's line, far from it
  if c1 * c2 > 0 then
    local near = 4 * DIST_EPS2 * (ex * ex + ey * ey)
    if c1 * c1 > near and c2 * c2 > near then return false end
  end
  return segDist2(cx, cy, ax, ay, bx, by) <= DIST_EPS2
    or segDist2(dx, dy, ax, ay, bx, by) <= DIST_EPS2
    or segDist2(ax, ay, cx, cy, dx, dy) <= DIST_EPS2
    or segDist2(bx, by, cx, cy, dx, dy) <= DIST_EPS2
end

--- Vertex indices 1..m sorted by U, then V, then index: the order of a sweep along U (ties
--- broken as if the sweep line were turned a little), and each vertex's rank in it.
local function sweepOrder(U, V, m)
  local order, rank = hull.order(U, V, m), {}
  for k = 1, m do rank[order[k]] = k end
  return order, rank
end

-- The sweep status: an ordered list of positive integer ids, bottom to top, as a skip list
-- (Pugh 1990). Node 0 is the head on every level; level 1 links every id, so prv[1][id] and
-- nxt[1][id] are its neighbours (0 or nil at the ends). The levels come from a seeded
-- Park-Miller generator (Park and Miller, Comm. ACM 31, 1988): the same runs on every VM, and
-- math.random's state is left alone.
local MAX_LEVEL = 16

local function newStatus()
  local nxt, prv = {}, {}
  for l = 1, MAX_LEVEL do nxt[l], prv[l] = {}, {} end
  return { nxt = nxt, prv = prv, height = {}, level = 1, seed = 1, path = {} }
end

--- The last id e of the list with before(e) true (0 if none); before must hold on a prefix of
--- the list. Leaves in st.path, per level, the last node passed.
local function statusLast(st, before)
  local nxt, path = st.nxt, st.path
  local x = 0
  for l = st.level, 1, -1 do
    local nl = nxt[l]
    local y = nl[x]
    while y and before(y) do
      x = y
      y = nl[x]
    end
    path[l] = x
  end
  return x
end

--- Insert id after the last e with before(e) true.
local function statusInsert(st, id, before)
  statusLast(st, before)
  local seed = st.seed * 16807 % 2147483647
  st.seed = seed
  local h, u = 1, seed / 2147483647
  while u < 0.25 and h < MAX_LEVEL do h, u = h + 1, u * 4 end
  local path = st.path
  for l = st.level + 1, h do path[l] = 0 end
  if h > st.level then st.level = h end
  local nxt, prv = st.nxt, st.prv
  for l = 1, h do
    local nl, pl = nxt[l], prv[l]
    local p = path[l]
    local y = nl[p]
    nl[id], pl[id], nl[p] = y, p, id
    if y then pl[y] = id end
  end
  st.height[id] = h
end

local function statusRemove(st, id)
  local nxt, prv = st.nxt, st.prv
  for l = 1, st.height[id] do
    local nl, pl = nxt[l], prv[l]
    local p, y = pl[id], nl[id]
    nl[p] = y
    if y then pl[y] = p end
    nl[id], pl[id] = nil, nil
  end
  st.height[id] = nil
end

--- Are edges i and j (edge k runs from vertex k to vertex k % m + 1) neighbours on the outline?
local function adjacent(i, j, m)
  local d = i - j
  return d == 1 or d == -1 or d == m - 1 or d == 1 - m
end

--- Shamos-Hoey sweep along U (V across it) over the outline's edges, looking for two
--- non-adjacent edges that meet (segmentsMeet, in the working coordinates X, Y). Returns such
--- a pair of edge indices, or nil.
---
--- Every pair of edges that become neighbours in the status is tested, so, as in the exact
--- algorithm, the first crossing along the sweep is found. With the tolerance: a comparison
--- closer than GAP_EPS means the two edges touch (tested at once, or, for edges sharing a
--- vertex, ordered by their directions there, which the spike check keeps apart); otherwise
--- it is exact in sign. An edge t passing within DIST_EPS of a vertex v whose U lies within
--- t's span is a neighbour of one of v's two edges when the sweep reaches v (anything between
--- them there would be even closer to one of them), so that pair is tested; when the two
--- edges at v and t are themselves adjacent, the other edges beside them are tested too.
--- A vertex outside t's span along U is caught by the sweep along V (the caller runs both),
--- and one outside both spans lies within 2 * DIST_EPS of an end of t (closeVertices).
local function crossingSweep(U, V, m, X, Y)
  local order, rank = sweepOrder(U, V, m)
  local lo, hi = {}, {}
  for e = 1, m do
    local f = e % m + 1
    if rank[e] < rank[f] then lo[e], hi[e] = e, f else lo[e], hi[e] = f, e end
  end

  local found1, found2
  -- record (i, j) when non-adjacent and meeting
  local function test(i, j)
    if not found1 and not adjacent(i, j, m) and segmentsMeet(X, Y, i, i % m + 1, j, j % m + 1) then
      found1, found2 = i, j
    end
  end
  -- status neighbours i (below) and j (above)
  local function neighbours(i, j)
    if adjacent(i, j, m) then
      if j % m + 1 == i then i, j = j, i end -- j follows i on the outline
      test((i + m - 2) % m + 1, j)
      test(i, j % m + 1)
    else
      test(i, j)
    end
  end

  local s, p, r -- the edge being inserted, its first and its last end
  local function above(t) -- does s go above the status edge t?
    local a, b = lo[t], hi[t]
    local du = U[b] - U[a]
    local gap = 0 -- along V, from t to p; an edge parallel to V spans p when it is in the status
    if du > 0 then gap = (V[p] - V[a]) - (U[p] - U[a]) / du * (V[b] - V[a]) end
    if gap > GAP_EPS then return true end
    if gap < -GAP_EPS then return false end
    if adjacent(s, t, m) then
      if a == p then -- both leave p: by direction
        return (U[b] - U[p]) * (V[r] - V[p]) - (V[b] - V[p]) * (U[r] - U[p]) > 0
      elseif b == p then -- t ends where s starts: either side
        return true
      end
      -- both end at r
      return (U[a] - U[r]) * (V[p] - V[r]) - (V[a] - V[r]) * (U[p] - U[r]) < 0
    end
    test(s, t)
    return gap > 0
  end

  local st = newStatus()
  local prv1, nxt1 = st.prv[1], st.nxt[1]
  for k = 1, m do
    local v = order[k]
    local ein, eout = (v + m - 2) % m + 1, v
    -- edges starting at v, then edges ending at v
    for pass = 1, 2 do
      local e = pass == 1 and ein or eout
      if lo[e] == v then
        s, p, r = e, v, hi[e]
        statusInsert(st, e, above)
        local below, abv = prv1[e], nxt1[e]
        if below ~= 0 then neighbours(below, e) end
        if abv then neighbours(e, abv) end
        if found1 then return found1, found2 end
      end
    end
    for pass = 1, 2 do
      local e = pass == 1 and ein or eout
      if hi[e] == v then
        local below, abv = prv1[e], nxt1[e]
        statusRemove(st, e)
        if below ~= 0 and abv then neighbours(below, abv) end
        if found1 then return found1, found2 end
      end
    end
  end
  return nil
end

--- The key of cell number c in closeVertices' tables: c + 0.5 below 2^52 (exact there, and
--- apart from the whole numbers kept above). On a grid outline the cell numbers are multiples
--- of a large power of two, and Lua 5.3 hashes a whole number by its low bits alone, so that
--- they all fell in one chain (a 10,000-vertex comb spent 0.15 s there); other numbers are
--- hashed by all their bits. The cells, and the order in which they are visited, are the same.
local function cellKey(c)
  if c < 2 ^ 52 and c > -2 ^ 52 then return c + 0.5 end
  return c
end

--- Pairs of vertices closer than 4 * DIST_EPS along both axes (a grid of CELL-sized cells):
--- for each, the edges at the one and at the other are tested. Returns a meeting pair of
--- non-adjacent edges, or nil.
local function closeVertices(X, Y, m)
  local grid = {}
  local lim = 4 * DIST_EPS
  for v = 1, m do
    local cx, cy = floor(X[v] / CELL), floor(Y[v] / CELL)
    -- (offsets, not a loop from cx - 1 to cx + 1: beyond 2^53, cx + 1 == cx)
    for ox = -1, 1 do
      local col = grid[cellKey(cx + ox)]
      if col then
        for oy = -1, 1 do
          local cell = col[cellKey(cy + oy)]
          if cell then
            for k = 1, #cell do
              local u = cell[k]
              if abs(X[u] - X[v]) <= lim and abs(Y[u] - Y[v]) <= lim then
                local eu, ev = { (u + m - 2) % m + 1, u }, { (v + m - 2) % m + 1, v }
                for a = 1, 2 do
                  for b = 1, 2 do
                    local i, j = eu[a], ev[b]
                    if not adjacent(i, j, m) and i ~= j
                      and segmentsMeet(X, Y, i, i % m + 1, j, j % m + 1) then
                      return i, j
                    end
                  end
                end
              end
            end
          end
        end
      end
    end
    local kx, ky = cellKey(cx), cellKey(cy)
    local col = grid[kx]
    if not col then
      col = {}
      grid[kx] = col
    end
    local cell = col[ky]
    if not cell then
      cell = {}
      col[ky] = cell
    end
    cell[#cell + 1] = v
  end
  return nil
end

-- Up to this many vertices, prepare first tests every pair of non-adjacent edges: when none
-- meets, neither would any pair closeVertices and the sweeps test (they test such pairs with
-- segmentsMeet, and report only one that meets), so their answer, none, is known. Only when
-- a pair meets do they run, for the same answer as always (the same pair in the error). A
-- few vertices' pairs cost less than the sweeps, whose skip lists, sorts and closures a
-- small polygon (a level's) pays for in full: a whole decomposition of an 8-vertex star
-- 163 -> 92 us on Lua 5.4, of 32 vertices 776 -> 484.
local FEW = 32

--- Do two non-adjacent edges of the outline meet (segmentsMeet)? Every pair is tested.
local function anyMeet(X, Y, m)
  for i = 1, m - 2 do
    for j = i + 2, i == 1 and m - 1 or m do
      if segmentsMeet(X, Y, i, i + 1, j, j % m + 1) then return true end
    end
  end
  return false
end

--- Clean and validate the outline.
--- Returns the scaled working coordinates X, Y (1..m, counter-clockwise, no duplicate or
--- collinear points), the input index of each working vertex, m and the scale; or nil, err.
local function prepare(xs, ys, n)
  local distinct = countDistinct(xs, ys, n)
  if distinct < 3 then
    return nil, ('needs at least 3 distinct points, got %d'):format(distinct)
  end

  local xmin, xmax, ymin, ymax = xs[1], xs[1], ys[1], ys[1]
  for i = 2, n do
    local x, y = xs[i], ys[i]
    if x < xmin then xmin = x elseif x > xmax then xmax = x end
    if y < ymin then ymin = y elseif y > ymax then ymax = y end
  end
  local extent = max(xmax - xmin, ymax - ymin)
  -- products of coordinate differences must stay finite (64 leaves room for sums of them)
  if extent * extent * 64 >= HUGE then return nil, 'coordinates too large' end
  -- below this, products of coordinate differences underflow towards subnormal numbers
  if extent < 1e-140 then return nil, 'outline too small' end
  local s = 1.0 -- a float: on Lua 5.3+ an integer would wrap around when doubled
  while extent * s > 1 do s = s * 0.5 end
  while extent * s < 0.5 do s = s * 2 end

  -- scaled copy without consecutive duplicates (also last == first)
  local X, Y, id, m = {}, {}, {}, 0
  for i = 1, n do
    local x, y = xs[i] * s, ys[i] * s
    local dup = false
    if m > 0 then
      local dx, dy = x - X[m], y - Y[m]
      dup = dx * dx + dy * dy <= DIST_EPS2
    end
    if not dup then
      m = m + 1
      X[m], Y[m], id[m] = x, y, i
    end
  end
  while m > 1 do
    local dx, dy = X[m] - X[1], Y[m] - Y[1]
    if dx * dx + dy * dy > DIST_EPS2 then break end
    X[m], Y[m], id[m] = nil, nil, nil
    m = m - 1
  end
  if m < 3 then return nil, 'outline has zero area' end -- distinct points, but closer than DIST_EPS

  -- all points on one line (within DIST_EPS): zero area
  local far, fd = 1, -1
  for i = 2, m do
    local dx, dy = X[i] - X[1], Y[i] - Y[1]
    local d = dx * dx + dy * dy
    if d > fd then far, fd = i, d end
  end
  do
    local lx, ly, len = X[far] - X[1], Y[far] - Y[1], sqrt(fd)
    local flat = true
    for i = 2, m do
      if abs(lx * (Y[i] - Y[1]) - ly * (X[i] - X[1])) > DIST_EPS * len then
        flat = false
        break
      end
    end
    if flat then return nil, 'outline has zero area' end
  end

  -- spikes: adjacent edges folding back onto each other
  for i = 1, m do
    local a, c = i - 1, i + 1
    if a < 1 then a = m end
    if c > m then c = 1 end
    local cr, len, dot = corner(X, Y, a, i, c)
    if abs(cr) <= TURN_EPS * len and dot < 0 then
      return nil, ('outline folds back on itself at vertex %d (spike)'):format(id[i])
    end
  end

  -- non-adjacent edges that cross or touch; edge k runs from input vertex k to the next kept one
  local ei, ej
  if m > FEW or anyMeet(X, Y, m) then
    ei, ej = closeVertices(X, Y, m)
    if not ei then ei, ej = crossingSweep(X, Y, m, X, Y) end
    if not ei then ei, ej = crossingSweep(Y, X, m, X, Y) end
  end
  if ei then
    if id[ei] > id[ej] then ei, ej = ej, ei end
    return nil, ('outline intersects itself (edges %d and %d)'):format(id[ei], id[ej])
  end

  -- drop collinear points (a linked list; re-examine the neighbour after each removal)
  local nxt, prv = {}, {}
  for i = 1, m do
    nxt[i] = i % m + 1
    prv[i] = (i + m - 2) % m + 1
  end
  local count, v, stable = m, 1, 0
  while stable < count and count > 3 do
    local a, c = prv[v], nxt[v]
    local cr, len, dot = corner(X, Y, a, v, c)
    if abs(cr) <= TURN_EPS * len then
      if dot < 0 then
        return nil, ('outline folds back on itself at vertex %d (spike)'):format(id[v])
      end
      nxt[a], prv[c] = c, a
      count, stable, v = count - 1, 0, a
    else
      stable, v = stable + 1, c
    end
  end

  local CX, CY, cid = {}, {}, {}
  for k = 1, count do
    CX[k], CY[k], cid[k] = X[v], Y[v], id[v]
    v = nxt[v]
  end

  local area2 = 0
  for k = 2, count - 1 do
    area2 = area2 + (CX[k] - CX[1]) * (CY[k + 1] - CY[1]) - (CX[k + 1] - CX[1]) * (CY[k] - CY[1])
  end
  if abs(area2 / (s * s)) >= HUGE then return nil, 'coordinates too large' end
  if area2 == 0 or count < 3 then return nil, 'outline has zero area' end
  if area2 < 0 then
    for k = 1, floor(count / 2) do
      local o = count + 1 - k
      CX[k], CX[o] = CX[o], CX[k]
      CY[k], CY[o] = CY[o], CY[k]
      cid[k], cid[o] = cid[o], cid[k]
    end
  end
  return CX, CY, cid, count
end

--- Diagonals that split the counter-clockwise outline into pieces monotone along the sweep
--- (x, ties broken by y): de Berg et al. section 3.2 with the sweep turned to run along x,
--- so "left of the vertex" becomes "below it". The status holds the edges with the inside
--- above them (those running forward along the sweep), each with its helper. Returns the
--- diagonals as two lists of ends and their count, or nil when a comparison is too close to
--- call (numerical degeneracy).
local function monotoneDiagonals(X, Y, m, order, rank)
  local st = newStatus()
  local helper, isMerge = {}, {}
  local da, db, nd = {}, {}, 0
  local v -- the vertex being placed
  local bad = false
  local function above(t) -- is v above edge t (from t to t % m + 1, forward along the sweep)?
    local b = t % m + 1
    local dx = X[b] - X[t]
    if dx <= 0 then -- along y and spanning v: v would lie on it
      bad = true
      return false
    end
    local gap = (Y[v] - Y[t]) - (X[v] - X[t]) / dx * (Y[b] - Y[t])
    if gap > GAP_EPS then return true end
    if gap < -GAP_EPS then return false end
    bad = true
    return gap > 0
  end
  local function diagonal(a, b)
    nd = nd + 1
    da[nd], db[nd] = a, b
  end
  -- the status edge right below v, or nil
  local function below()
    local j = statusLast(st, above)
    if j == 0 or bad then return nil end
    return j
  end

  for k = 1, m do
    v = order[k]
    local p, q = (v + m - 2) % m + 1, v % m + 1
    local pBefore, qBefore = rank[p] < rank[v], rank[q] < rank[v]
    local reflex = false
    if pBefore == qBefore then reflex = corner(X, Y, p, v, q) < 0 end
    if not pBefore and not qBefore then -- start, or split when reflex
      if reflex then
        local j = below()
        if not j then return nil end
        diagonal(v, helper[j])
        helper[j] = v
      end
      statusInsert(st, v, above)
      helper[v] = v
    elseif pBefore and qBefore then -- end, or merge when reflex
      if isMerge[helper[p]] then diagonal(v, helper[p]) end
      statusRemove(st, p)
      if reflex then
        isMerge[v] = true
        local j = below()
        if not j then return nil end
        if isMerge[helper[j]] then diagonal(v, helper[j]) end
        helper[j] = v
      end
    elseif pBefore then -- regular, the inside above
      if isMerge[helper[p]] then diagonal(v, helper[p]) end
      statusRemove(st, p)
      statusInsert(st, v, above)
      helper[v] = v
    else -- regular, the inside below
      local j = below()
      if not j then return nil end
      if isMerge[helper[j]] then diagonal(v, helper[j]) end
      helper[j] = v
    end
    if bad then return nil end
  end
  return da, db, nd
end

--- The faces cut out of the outline by the diagonals, each a list of vertices in
--- counter-clockwise order; or nil (numerical degeneracy). Around a vertex, its diagonals
--- (a handful at most: one per helper it was, one or two of its own) are sorted
--- counter-clockwise from its outline edge forward; a face turns, at each vertex, onto the
--- edge just clockwise of the one it arrived along. That sort is the one decision here without
--- a margin: it can only go wrong for two diagonals within about 1e-16 radians of each other
--- (one nearly through the other's far end); faces walked wrongly would then most likely fail
--- the checks that follow (monotone chains, triangle count), though nothing guarantees it.
local function faces(X, Y, m, da, db, nd)
  local fan = {} -- fan[v]: {next vertex, diagonal ends counter-clockwise, previous vertex}
  for k = 1, nd do
    for dir = 1, 2 do
      local v, w = da[k], db[k]
      if dir == 2 then v, w = w, v end
      local f = fan[v]
      if not f then
        f = { v % m + 1 }
        fan[v] = f
      end
      f[#f + 1] = w
    end
  end
  for v, f in pairs(fan) do
    -- insertion sort of the diagonal ends by angle from the edge forward (all lie inside the
    -- corner, whose angle is below 2 pi): the half turn first, then cross products
    local bx, by = X[f[1]] - X[v], Y[f[1]] - Y[v]
    local function half(w)
      local wx, wy = X[w] - X[v], Y[w] - Y[v]
      local c = bx * wy - by * wx
      if c > 0 or (c == 0 and bx * wx + by * wy > 0) then return 0 end
      return 1
    end
    local function before(w1, w2)
      local h1, h2 = half(w1), half(w2)
      if h1 ~= h2 then return h1 < h2 end
      return (X[w1] - X[v]) * (Y[w2] - Y[v]) - (Y[w1] - Y[v]) * (X[w2] - X[v]) > 0
    end
    for i = 3, #f do
      local w, j = f[i], i - 1
      while j >= 2 and before(w, f[j]) do
        f[j + 1] = f[j]
        j = j - 1
      end
      f[j + 1] = w
    end
    f[#f + 1] = (v + m - 2) % m + 1
  end

  -- the vertex after w on the face that arrives at w from u
  local function turn(u, w)
    local f = fan[w]
    if not f then return w % m + 1 end -- u is w's previous vertex
    for i = 2, #f do
      if f[i] == u then return f[i - 1] end
    end
    return nil
  end

  local out, seen = {}, {}
  local limit = m + 2 * nd
  local function walk(a, b)
    local key = a * (m + 1) + b
    if seen[key] then return true end
    local face, u, w = {}, a, b
    repeat
      seen[u * (m + 1) + w] = true
      face[#face + 1] = u
      if #face > limit then return false end
      local x = turn(u, w)
      if not x then return false end
      u, w = w, x
    until u == a and w == b
    out[#out + 1] = face
    return true
  end
  for v = 1, m do
    if not walk(v, v % m + 1) then return nil end
  end
  for k = 1, nd do
    if not walk(da[k], db[k]) or not walk(db[k], da[k]) then return nil end
  end
  return out
end

--- Triangulate one monotone face (counter-clockwise vertex list) with a stack (de Berg et al.
--- section 3.3), appending counter-clockwise triangles to tris from index t + 1. Returns the new
--- t, or nil when the face is not monotone (numerical degeneracy).
local function triangulateMonotone(X, Y, rank, face, tris, t)
  local k = #face
  if k == 3 then
    tris[t + 1], tris[t + 2], tris[t + 3] = face[1], face[2], face[3]
    return t + 3
  end
  local iMin, iMax = 1, 1
  for i = 2, k do
    if rank[face[i]] < rank[face[iMin]] then iMin = i end
    if rank[face[i]] > rank[face[iMax]] then iMax = i end
  end
  -- merge the lower chain (forward from iMin) and the upper one (backward) in sweep order;
  -- chain 1 is the lower chain, 2 the upper one
  local u, chain = { face[iMin] }, { 1 }
  local i, j = iMin % k + 1, (iMin + k - 2) % k + 1
  local lastLo, lastUp = rank[face[iMin]], rank[face[iMin]]
  for n = 2, k - 1 do
    local takeLo
    if i == iMax then takeLo = false
    elseif j == iMax then takeLo = true
    else takeLo = rank[face[i]] < rank[face[j]] end
    if takeLo then
      if rank[face[i]] < lastLo then return nil end
      u[n], chain[n], lastLo = face[i], 1, rank[face[i]]
      i = i % k + 1
    else
      if rank[face[j]] < lastUp then return nil end
      u[n], chain[n], lastUp = face[j], 2, rank[face[j]]
      j = (j + k - 2) % k + 1
    end
  end
  if i ~= iMax or j ~= iMax then return nil end
  u[k] = face[iMax]

  -- the triangle of w (on chain c) and the consecutive stack vertices a, b (other chain, a first)
  local function fan(w, c, a, b)
    if c == 1 then
      tris[t + 1], tris[t + 2], tris[t + 3] = w, b, a
    else
      tris[t + 1], tris[t + 2], tris[t + 3] = w, a, b
    end
    t = t + 3
  end

  local S, top = { 1, 2 }, 2 -- positions in u
  for n = 3, k - 1 do
    local w, c = u[n], chain[n]
    if c ~= chain[S[top]] then
      for q = top, 2, -1 do fan(w, c, u[S[q - 1]], u[S[q]]) end
      S[1], S[2], top = n - 1, n, 2
    else
      local last = u[S[top]]
      local lastPos = S[top]
      top = top - 1
      while top >= 1 do
        local a = u[S[top]]
        if c == 1 then
          if not convex(X, Y, a, last, w) then break end
          tris[t + 1], tris[t + 2], tris[t + 3] = a, last, w
        else
          if not convex(X, Y, w, last, a) then break end
          tris[t + 1], tris[t + 2], tris[t + 3] = w, last, a
        end
        t = t + 3
        last, lastPos = a, S[top]
        top = top - 1
      end
      S[top + 1], S[top + 2] = lastPos, n
      top = top + 2
    end
  end
  local c = chain[S[top]] == 1 and 2 or 1
  for q = top, 2, -1 do fan(u[k], c, u[S[q - 1]], u[S[q]]) end
  return t
end

--- Triangulation of the cleaned counter-clockwise outline: a flat list {a1, b1, c1, a2, ...}
--- of counter-clockwise triangles (working indices), or nil, err.
local function triangulate(X, Y, m)
  local order, rank = sweepOrder(X, Y, m)
  local da, db, nd = monotoneDiagonals(X, Y, m, order, rank)
  if not da then return nil, DEGENERATE_TRI end
  local list = faces(X, Y, m, da, db, nd)
  if not list then return nil, DEGENERATE_TRI end
  local tris, t = {}, 0
  for f = 1, #list do
    t = triangulateMonotone(X, Y, rank, list[f], tris, t)
    if not t then return nil, DEGENERATE_TRI end
  end
  if t ~= 3 * (m - 2) then return nil, DEGENERATE_TRI end
  return tris
end

--- How sharp the merged corner a -> u -> b would be: nil when reflex (beyond TURN_EPS),
--- else a number increasing with the turn (about 0 for a straight corner, 2 for a U-turn).
local function mergedCorner(X, Y, a, u, b)
  local cr, len, dot = corner(X, Y, a, u, b)
  if cr < -TURN_EPS * len then return nil end
  if cr <= TURN_EPS * len and dot <= 0 then return nil end
  local cos = dot / len
  if cr >= 0 then return 1 - cos end
  return cos - 1
end

--- Hertel-Mehlhorn merging over a half-edge structure of the triangles. Returns a list of
--- faces, each a list of working indices in counter-clockwise order.
local function merge(X, Y, m, tris)
  local hfrom, hto, hnext, hprev, twin = {}, {}, {}, {}, {}
  local nh = #tris
  local byKey = {}
  for h = 1, nh do
    local base = h - (h - 1) % 3 -- first half-edge of this triangle
    local nextH = h + 1
    if nextH > base + 2 then nextH = base end
    local prevH = h - 1
    if prevH < base then prevH = base + 2 end
    hfrom[h], hto[h], hnext[h], hprev[h] = tris[h], tris[nextH], nextH, prevH
    byKey[tris[h] * (m + 1) + tris[nextH]] = h
  end
  for h = 1, nh do
    local o = byKey[hto[h] * (m + 1) + hfrom[h]]
    if o then twin[h] = o end
  end

  -- score of removing the diagonal h (u -> v) with twin t (v -> u); nil if not convex
  local function score(h)
    local t = twin[h]
    local su = mergedCorner(X, Y, hfrom[hprev[h]], hfrom[h], hto[hnext[t]])
    if not su then return nil end
    local sv = mergedCorner(X, Y, hfrom[hprev[t]], hto[h], hto[hnext[h]])
    if not sv then return nil end
    if sv < su then return sv end
    return su
  end

  -- Greedy: remove the removable diagonal whose merged corners are sharpest (ties: the lower
  -- half-edge number), until none is. A binary heap of (score, diagonal, version) entries;
  -- an entry is stale once its diagonal is gone or rescored.
  local hs, hh, hv, size = {}, {}, {}, 0
  local version = {}
  -- (sifts that move a hole rather than swap entries, the comparisons written out: the same
  -- comparisons and the same heap as with a swap and a comparison function, which were most of
  -- the merging's time on Lua 5.1-5.4; an entry (s, h) comes first when its score is higher, or
  -- equal with a lower h)
  local function push(h)
    local sc = score(h)
    if not sc then return end
    size = size + 1
    local i = size
    while i > 1 do
      local parent = floor(i / 2)
      local sp = hs[parent]
      if not (sc > sp or (sc == sp and h < hh[parent])) then break end
      hs[i], hh[i], hv[i] = sp, hh[parent], hv[parent]
      i = parent
    end
    hs[i], hh[i], hv[i] = sc, h, version[h]
  end
  local function pop()
    local h, ver = hh[1], hv[1]
    local es, eh, ev = hs[size], hh[size], hv[size] -- the last entry, sifted down from the top
    hs[size], hh[size], hv[size] = nil, nil, nil
    size = size - 1
    if size == 0 then return h, ver end
    local i = 1
    while true do
      local c = 2 * i
      if c > size then break end
      local sc = hs[c]
      if c + 1 <= size then
        local sr = hs[c + 1]
        if sr > sc or (sr == sc and hh[c + 1] < hh[c]) then c, sc = c + 1, sr end
      end
      if not (sc > es or (sc == es and hh[c] < eh)) then break end
      hs[i], hh[i], hv[i] = sc, hh[c], hv[c]
      i = c
    end
    hs[i], hh[i], hv[i] = es, eh, ev
    return h, ver
  end

  for h = 1, nh do
    local o = twin[h]
    if o and h < o then
      version[h] = 0
      push(h)
    end
  end
  local touched = {}
  while size > 0 do
    local best, ver = pop()
    if hfrom[best] and version[best] == ver then
      local t = twin[best]
      local hp, hn, tp, tn = hprev[best], hnext[best], hprev[t], hnext[t]
      hnext[hp], hprev[tn] = tn, hp
      hnext[tp], hprev[hn] = hn, tp
      hfrom[best], hfrom[t] = nil, nil
      -- the diagonals among the four relinked half-edges get new scores
      touched[1], touched[2], touched[3], touched[4] = hp, hn, tp, tn
      for k = 1, 4 do
        local d = touched[k]
        local o = twin[d]
        if o then
          if o < d then d = o end
          version[d] = version[d] + 1
          push(d)
        end
      end
    end
  end

  local out, seen = {}, {}
  for h = 1, nh do
    if hfrom[h] and not seen[h] then
      local face, e = {}, h
      repeat
        seen[e] = true
        face[#face + 1] = hfrom[e]
        e = hnext[e]
      until e == h
      out[#out + 1] = face
    end
  end
  return out
end

--- Turn a face into an output piece: drop straight corners (left by merging across a straight
--- angle), check strict convexity in the caller's coordinates, map to input coordinates.
local function finish(X, Y, face, xs, ys, id)
  local k = #face
  local nxt, prv = {}, {}
  for i = 1, k do
    nxt[i] = i % k + 1
    prv[i] = (i + k - 2) % k + 1
  end
  local v, stable = 1, 0
  while stable < k and k > 3 do
    local a, c = prv[v], nxt[v]
    local cr, len = corner(X, Y, face[a], face[v], face[c])
    if abs(cr) <= TURN_EPS * len then
      nxt[a], prv[c] = c, a
      k, stable, v = k - 1, 0, a
    else
      stable, v = stable + 1, c
    end
  end
  local piece = {}
  for i = 1, k do
    local a, c = id[face[prv[v]]], id[face[nxt[v]]]
    local b = id[face[v]]
    -- the caller will see these exact coordinates: insist on a strict left turn there too
    local cr = (xs[b] - xs[a]) * (ys[c] - ys[b]) - (ys[b] - ys[a]) * (xs[c] - xs[b])
    if cr <= 0 or not convex(X, Y, face[prv[v]], face[v], face[nxt[v]]) then return nil end
    piece[2 * i - 1], piece[2 * i] = xs[b], ys[b]
    v = nxt[v]
  end
  return piece
end

--- Split a simple polygon (either winding) into few convex pieces that tile it exactly.
--- Consecutive duplicate and collinear points are dropped first. The pieces are made of the
--- input's own coordinates: each is a flat array {x1, y1, x2, y2, ...} of a strictly convex
--- polygon with positive shoelace area (counter-clockwise), no repeated and no collinear
--- vertices. Rejected outlines give nil and a short lower-case reason, e.g.
--- "outline intersects itself (edges 2 and 5)" (edge k starts at input vertex k),
--- "outline folds back on itself at vertex 4 (spike)", "needs at least 3 distinct points, got 2",
--- "outline has zero area", "coordinates too large", "outline too small" (extent below 1e-140).
--- Takes O(n log n) time.
---@param xs number[] x coordinates (1..n), finite
---@param ys number[] y coordinates (1..n), finite
---@param n integer vertex count
---@return number[][]|nil pieces convex pieces, each {x1, y1, x2, y2, ...} counter-clockwise
---@return string|nil err why the outline was rejected
function decompose.decompose(xs, ys, n)
  n = floor(n)
  local X, Y, id, m = prepare(xs, ys, n)
  if not X then return nil, Y end

  local list
  local allConvex = true
  for i = 1, m do
    if not convex(X, Y, (i + m - 2) % m + 1, i, i % m + 1) then
      allConvex = false
      break
    end
  end
  if allConvex then
    local face = {}
    for i = 1, m do face[i] = i end
    list = { face }
  else
    local tris, err = triangulate(X, Y, m)
    if not tris then return nil, err end
    list = merge(X, Y, m, tris)
  end

  local pieces = {}
  for k = 1, #list do
    local piece = finish(X, Y, list[k], xs, ys, id)
    if not piece then return nil, DEGENERATE_MERGE end
    pieces[k] = piece
  end
  return pieces
end

return decompose
