--- Convex decomposition of simple polygons.
--
-- The outline is cleaned (duplicate and collinear points dropped), validated (at least three
-- distinct points, nonzero area, no self-intersection, no spike folding back onto itself),
-- triangulated by ear clipping and the triangles are merged back into convex pieces with the
-- Hertel-Mehlhorn rule: a diagonal is removed when the union of the two pieces it separates
-- is still convex.
--
-- Sources (the algorithms, written here from their descriptions):
--   * ear clipping: D. Eberly, "Triangulation by Ear Clipping", Geometric Tools;
--     G. H. Meisters, "Polygons have ears", Amer. Math. Monthly 82 (1975).
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
--     closer than this to a non-adjacent edge touches it; a triangle blocks points this close.
--   * TURN_EPS (1e-12): three points a, b, c are collinear when
--     |cross(b - a, c - b)| <= TURN_EPS * |b - a| * |c - b|, i.e. the turn at b is below
--     about 1e-12 radians. Convex means a turn above that, strictly.
-- The pieces are made of the caller's own coordinates (never recomputed points), so a piece
-- vertex is always exactly an input vertex.
local decompose = {}

local abs, sqrt, floor = math.abs, math.sqrt, math.floor
local HUGE = math.huge

local DIST_EPS = 1e-12
local DIST_EPS2 = DIST_EPS * DIST_EPS
local TURN_EPS = 1e-12

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

--- Squared distance from point p to the segment a-b.
local function segDist2(X, Y, p, a, b)
  local ex, ey = X[b] - X[a], Y[b] - Y[a]
  local px, py = X[p] - X[a], Y[p] - Y[a]
  local len2 = ex * ex + ey * ey
  local t = 0
  if len2 > 0 then
    t = (px * ex + py * ey) / len2
    if t < 0 then t = 0 elseif t > 1 then t = 1 end
  end
  local dx, dy = px - t * ex, py - t * ey
  return dx * dx + dy * dy
end

--- Sign of cross(b - a, p - a): 1 left, -1 right, 0 on the line (computed in floating point).
local function side(X, Y, a, b, p)
  local v = (X[b] - X[a]) * (Y[p] - Y[a]) - (Y[b] - Y[a]) * (X[p] - X[a])
  if v > 0 then return 1 elseif v < 0 then return -1 end
  return 0
end

--- Do the segments a-b and c-d (no shared endpoint) cross or come within DIST_EPS?
local function segmentsMeet(X, Y, a, b, c, d)
  -- bounding boxes, grown by the tolerance
  local e = DIST_EPS
  if math.max(X[a], X[b]) + e < math.min(X[c], X[d]) or math.max(X[c], X[d]) + e < math.min(X[a], X[b])
    or math.max(Y[a], Y[b]) + e < math.min(Y[c], Y[d]) or math.max(Y[c], Y[d]) + e < math.min(Y[a], Y[b]) then
    return false
  end
  local s1, s2 = side(X, Y, a, b, c), side(X, Y, a, b, d)
  local s3, s4 = side(X, Y, c, d, a), side(X, Y, c, d, b)
  if s1 * s2 < 0 and s3 * s4 < 0 then return true end -- proper crossing
  return segDist2(X, Y, c, a, b) <= DIST_EPS2 or segDist2(X, Y, d, a, b) <= DIST_EPS2
    or segDist2(X, Y, a, c, d) <= DIST_EPS2 or segDist2(X, Y, b, c, d) <= DIST_EPS2
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
  local extent = math.max(xmax - xmin, ymax - ymin)
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
  for i = 1, m - 2 do
    local i2 = i + 1
    local last = m
    if i == 1 then last = m - 1 end
    for j = i + 2, last do
      local j2 = j + 1
      if j2 > m then j2 = 1 end
      if segmentsMeet(X, Y, i, i2, j, j2) then
        return nil, ('outline intersects itself (edges %d and %d)'):format(id[i], id[j])
      end
    end
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

--- Is vertex b of a -> b -> c strictly convex (a left turn above TURN_EPS)?
local function convex(X, Y, a, b, c)
  local cr, len = corner(X, Y, a, b, c)
  return cr > TURN_EPS * len
end

--- Ear clipping. Returns a flat list of triangles {a1, b1, c1, a2, ...} (working indices,
--- counter-clockwise), or nil, err.
local function triangulate(X, Y, m)
  local nxt, prv = {}, {}
  for i = 1, m do
    nxt[i] = i % m + 1
    prv[i] = (i + m - 2) % m + 1
  end

  -- Is any remaining vertex other than a, b, c inside or on the triangle a, b, c
  -- (within DIST_EPS of it)? Every vertex is tested, not only reflex ones, so that a
  -- vertex touching the new diagonal a-c blocks the ear too.
  local function blocked(a, b, c)
    local ax, ay, bx, by, cx, cy = X[a], Y[a], X[b], Y[b], X[c], Y[c]
    local xlo = math.min(ax, bx, cx) - DIST_EPS
    local xhi = math.max(ax, bx, cx) + DIST_EPS
    local ylo = math.min(ay, by, cy) - DIST_EPS
    local yhi = math.max(ay, by, cy) + DIST_EPS
    local abx, aby, bcx, bcy, cax, cay = bx - ax, by - ay, cx - bx, cy - by, ax - cx, ay - cy
    local tab = -DIST_EPS * sqrt(abx * abx + aby * aby)
    local tbc = -DIST_EPS * sqrt(bcx * bcx + bcy * bcy)
    local tca = -DIST_EPS * sqrt(cax * cax + cay * cay)
    local p = nxt[c]
    while p ~= a do
      local px, py = X[p], Y[p]
      if px >= xlo and px <= xhi and py >= ylo and py <= yhi
        and abx * (py - ay) - aby * (px - ax) >= tab
        and bcx * (py - by) - bcy * (px - bx) >= tbc
        and cax * (py - cy) - cay * (px - cx) >= tca then
        return true
      end
      p = nxt[p]
    end
    return false
  end

  local ear = {}
  local function update(v)
    local a, c = prv[v], nxt[v]
    ear[v] = convex(X, Y, a, v, c) and not blocked(a, v, c)
  end
  for v = 1, m do update(v) end

  local tris, t = {}, 0
  local count, v = m, 1
  while count > 3 do
    -- Clipping an ear only changes the ear status of its two neighbours, except that a
    -- vertex blocked only by the clipped one may become an ear; a cached "not an ear" is
    -- thus pessimistic, so when no cached ear is left every status is recomputed.
    local found = false
    for pass = 1, 2 do
      if pass == 2 then
        local w = v
        for _ = 1, count do
          update(w)
          w = nxt[w]
        end
      end
      for _ = 1, count do
        if ear[v] then
          found = true
          break
        end
        v = nxt[v]
      end
      if found then break end
    end
    if not found then return nil, DEGENERATE_TRI end
    local a, c = prv[v], nxt[v]
    tris[t + 1], tris[t + 2], tris[t + 3] = a, v, c
    t = t + 3
    nxt[a], prv[c] = c, a
    ear[v] = nil
    count = count - 1
    update(a)
    update(c)
    v = c
  end
  local a, c = prv[v], nxt[v]
  if not convex(X, Y, a, v, c) then return nil, DEGENERATE_TRI end
  tris[t + 1], tris[t + 2], tris[t + 3] = a, v, c
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
  local function first(i, j) -- does entry i come before entry j?
    local si, sj = hs[i], hs[j]
    if si ~= sj then return si > sj end
    return hh[i] < hh[j]
  end
  local function swap(i, j)
    hs[i], hs[j] = hs[j], hs[i]
    hh[i], hh[j] = hh[j], hh[i]
    hv[i], hv[j] = hv[j], hv[i]
  end
  local function push(h)
    local sc = score(h)
    if not sc then return end
    size = size + 1
    hs[size], hh[size], hv[size] = sc, h, version[h]
    local i = size
    while i > 1 do
      local parent = floor(i / 2)
      if not first(i, parent) then break end
      swap(i, parent)
      i = parent
    end
  end
  local function pop()
    local h, ver = hh[1], hv[1]
    swap(1, size)
    hs[size], hh[size], hv[size] = nil, nil, nil
    size = size - 1
    local i = 1
    while true do
      local l = 2 * i
      if l > size then break end
      local c = l
      if l + 1 <= size and first(l + 1, l) then c = l + 1 end
      if not first(c, i) then break end
      swap(i, c)
      i = c
    end
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
---@param xs number[] x coordinates (1..n), finite
---@param ys number[] y coordinates (1..n), finite
---@param n integer vertex count
---@return number[][]|nil pieces convex pieces, each {x1, y1, x2, y2, ...} counter-clockwise
---@return string|nil err why the outline was rejected
function decompose.decompose(xs, ys, n)
  n = floor(n)
  local X, Y, id, m = prepare(xs, ys, n)
  if not X then return nil, Y end

  local faces
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
    faces = { face }
  else
    local tris, err = triangulate(X, Y, m)
    if not tris then return nil, err end
    faces = merge(X, Y, m, tris)
  end

  local pieces = {}
  for k = 1, #faces do
    local piece = finish(X, Y, faces[k], xs, ys, id)
    if not piece then return nil, DEGENERATE_MERGE end
    pieces[k] = piece
  end
  return pieces
end

return decompose
