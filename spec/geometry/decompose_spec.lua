local decompose = require('strike.geometry.decompose')
local PRNG = require('spec.helpers.prng')

local abs, sqrt, max, min = math.abs, math.sqrt, math.max, math.min
local cos, sin, pi, floor = math.cos, math.sin, math.pi, math.floor

--- Outline from a flat list {x1, y1, x2, y2, ...}.
local function outline(flat)
  local xs, ys = {}, {}
  for i = 1, #flat / 2 do
    xs[i], ys[i] = flat[2 * i - 1], flat[2 * i]
  end
  return xs, ys, #xs
end

--- Append the point (x, y) to a flat list.
local function push(flat, x, y)
  flat[#flat + 1] = x
  flat[#flat + 1] = y
end

--- The same outline in the other winding.
local function reversed(xs, ys, n)
  local rx, ry = {}, {}
  for i = 1, n do
    rx[i], ry[i] = xs[n + 1 - i], ys[n + 1 - i]
  end
  return rx, ry, n
end

--- Shoelace signed area.
local function signed_area(px, py, n)
  local s = 0
  for i = 1, n do
    local j = i % n + 1
    s = s + px[i] * py[j] - px[j] * py[i]
  end
  return s / 2
end

--- cross(b - a, c - b) for the corner a -> b -> c.
local function turn(ax, ay, bx, by, cx, cy)
  return (bx - ax) * (cy - by) - (by - ay) * (cx - bx)
end

--- Number of reflex corners of an outline (in its own winding; repeated points skipped).
local function reflex_count(xs, ys, n)
  local ux, uy = {}, {}
  for i = 1, n do
    if xs[i] ~= xs[i % n + 1] or ys[i] ~= ys[i % n + 1] then ux[#ux + 1], uy[#uy + 1] = xs[i], ys[i] end
  end
  xs, ys, n = ux, uy, #ux
  local sign = signed_area(xs, ys, n) > 0 and 1 or -1
  local r = 0
  for i = 1, n do
    local a, c = (i + n - 2) % n + 1, i % n + 1
    if sign * turn(xs[a], ys[a], xs[i], ys[i], xs[c], ys[c]) < 0 then r = r + 1 end
  end
  return r
end

--- Squared distance from (px, py) to the segment (ax, ay)-(bx, by).
local function seg_dist2(px, py, ax, ay, bx, by)
  local ex, ey = bx - ax, by - ay
  local len2 = ex * ex + ey * ey
  local t = 0
  if len2 > 0 then t = max(0, min(1, ((px - ax) * ex + (py - ay) * ey) / len2)) end
  local dx, dy = px - ax - t * ex, py - ay - t * ey
  return dx * dx + dy * dy
end

--- Is (px, py) inside the outline or within tol of its boundary? (crossing number)
local function in_outline(px, py, xs, ys, n, tol)
  local inside = false
  for i = 1, n do
    local j = i % n + 1
    if seg_dist2(px, py, xs[i], ys[i], xs[j], ys[j]) <= tol * tol then return true end
    local yi, yj = ys[i], ys[j]
    if (yi > py) ~= (yj > py) and px < (xs[j] - xs[i]) * (py - yi) / (yj - yi) + xs[i] then
      inside = not inside
    end
  end
  return inside
end

--- Does the segment a-b pass through the counter-clockwise convex polygon p shrunk by tol?
--- (Cyrus-Beck clipping against every edge's inner half-plane.)
local function segment_enters(ax, ay, bx, by, p, tol)
  local t0, t1 = 0, 1
  for i = 1, p.n do
    local j = i % p.n + 1
    local ex, ey = p.x[j] - p.x[i], p.y[j] - p.y[i]
    local shrink = tol * sqrt(ex * ex + ey * ey)
    local f0 = ex * (ay - p.y[i]) - ey * (ax - p.x[i]) - shrink
    local f1 = ex * (by - p.y[i]) - ey * (bx - p.x[i]) - shrink
    if f0 <= 0 and f1 <= 0 then return false end
    if f0 < 0 then
      t0 = max(t0, f0 / (f0 - f1))
    elseif f1 < 0 then
      t1 = min(t1, f0 / (f0 - f1))
    end
    if t0 >= t1 then return false end
  end
  return true
end

--- Do the convex polygons a and b overlap by more than tol? (SAT over both polygons' edge normals)
local function overlap(a, b, tol)
  for pass = 1, 2 do
    local p = pass == 1 and a or b
    for i = 1, p.n do
      local j = i % p.n + 1
      local nx, ny = p.y[i] - p.y[j], p.x[j] - p.x[i]
      local amin, amax, bmin, bmax = math.huge, -math.huge, math.huge, -math.huge
      for k = 1, a.n do
        local d = nx * a.x[k] + ny * a.y[k]
        amin, amax = min(amin, d), max(amax, d)
      end
      for k = 1, b.n do
        local d = nx * b.x[k] + ny * b.y[k]
        bmin, bmax = min(bmin, d), max(bmax, d)
      end
      if min(amax, bmax) - max(amin, bmin) <= tol * sqrt(nx * nx + ny * ny) then return false end
    end
  end
  return true
end

--- Do the pieces tile the outline exactly? Returns true, or false and what is wrong.
--- Each piece is a strictly convex counter-clockwise polygon; the pieces' interiors are pairwise
--- disjoint (SAT); each piece lies in the outline (its vertices and centroid are in it and no
--- outline edge passes through it); and the areas add up to the outline's. Together these
--- prove the pieces cover the outline exactly.
local function check_pieces(xs, ys, n, pieces)
  if type(pieces) ~= 'table' or #pieces == 0 then return false, 'no pieces' end
  -- work relative to the outline's corner so that offsets cost no precision
  local x0, y0, x1, y1 = xs[1], ys[1], xs[1], ys[1]
  for i = 2, n do
    x0, x1, y0, y1 = min(x0, xs[i]), max(x1, xs[i]), min(y0, ys[i]), max(y1, ys[i])
  end
  local scale = max(x1 - x0, y1 - y0)
  local tol = 1e-9 * scale
  local ox, oy = {}, {}
  for i = 1, n do ox[i], oy[i] = xs[i] - x0, ys[i] - y0 end
  local total = abs(signed_area(ox, oy, n))

  local polys, sum = {}, 0
  for k, piece in ipairs(pieces) do
    local m = #piece / 2
    if #piece % 2 ~= 0 or m < 3 then
      return false, ('piece %d has %d coordinates'):format(k, #piece)
    end
    local p = { n = m, x = {}, y = {} }
    for i = 1, m do
      local px, py = piece[2 * i - 1], piece[2 * i]
      p.x[i], p.y[i] = px - x0, py - y0
      -- a strict left turn at every vertex, in the coordinates as returned (no repeats, no collinear)
      local j, l = i % m + 1, (i + 1) % m + 1
      local t = turn(px, py, piece[2 * j - 1], piece[2 * j], piece[2 * l - 1], piece[2 * l])
      if t <= 0 or t ~= t then
        return false, ('piece %d is not strictly convex at vertex %d (turn %.17g)'):format(k, j, t)
      end
    end
    -- convex (not just locally): every vertex is on the inner side of every edge
    for i = 1, m do
      local j = i % m + 1
      local ex, ey = p.x[j] - p.x[i], p.y[j] - p.y[i]
      local slack = -tol * sqrt(ex * ex + ey * ey)
      for v = 1, m do
        if ex * (p.y[v] - p.y[i]) - ey * (p.x[v] - p.x[i]) < slack then
          return false, ('piece %d is not convex: vertex %d is outside edge %d'):format(k, v, i)
        end
      end
    end
    local area = signed_area(p.x, p.y, m)
    if area <= 0 or area ~= area then return false, ('piece %d has area %.17g'):format(k, area) end
    sum = sum + area
    -- inside the outline
    local cx, cy = 0, 0
    for i = 1, m do
      if not in_outline(p.x[i], p.y[i], ox, oy, n, tol) then
        return false, ('piece %d vertex %d is outside the outline'):format(k, i)
      end
      cx, cy = cx + p.x[i] / m, cy + p.y[i] / m
    end
    if not in_outline(cx, cy, ox, oy, n, tol) then
      return false, ('piece %d centroid is outside the outline'):format(k)
    end
    for i = 1, n do
      local j = i % n + 1
      if segment_enters(ox[i], oy[i], ox[j], oy[j], p, tol) then
        return false, ('outline edge %d passes through piece %d'):format(i, k)
      end
    end
    p.x0, p.x1, p.y0, p.y1 = math.huge, -math.huge, math.huge, -math.huge
    for i = 1, m do
      p.x0, p.x1 = min(p.x0, p.x[i]), max(p.x1, p.x[i])
      p.y0, p.y1 = min(p.y0, p.y[i]), max(p.y1, p.y[i])
    end
    polys[k] = p
  end

  if abs(sum - total) > 1e-9 * total or sum ~= sum then
    return false, ('pieces cover area %.17g, outline has %.17g'):format(sum, total)
  end

  for a = 1, #polys do
    local pa = polys[a]
    for b = a + 1, #polys do
      local pb = polys[b]
      if pa.x0 < pb.x1 - tol and pb.x0 < pa.x1 - tol and pa.y0 < pb.y1 - tol and pb.y0 < pa.y1 - tol
        and overlap(pa, pb, tol) then
        return false, ('pieces %d and %d overlap'):format(a, b)
      end
    end
  end
  return true
end

--- Decompose and check; returns the pieces.
local function decompose_ok(xs, ys, n)
  local pieces, err = decompose.decompose(xs, ys, n)
  assert.is_nil(err)
  local ok, msg = check_pieces(xs, ys, n, pieces)
  assert.is_true(ok, msg)
  return pieces
end

--- A star-shaped polygon: angles with gaps below pi, radii in [r0, r1].
local function star(k, r_out, r_in)
  local flat = {}
  for i = 0, 2 * k - 1 do
    local r = i % 2 == 0 and r_out or r_in
    local a = pi * i / k
    flat[#flat + 1] = r * cos(a)
    flat[#flat + 1] = r * sin(a)
  end
  return outline(flat)
end

--- A rectangular comb: a base with `teeth` teeth pointing up.
local function comb(teeth)
  local w = 2 * teeth - 1
  local flat = { 0, 0, w, 0 }
  for k = teeth - 1, 0, -1 do
    local x = 2 * k
    push(flat, x + 1, 3)
    push(flat, x, 3)
    if k > 0 then
      push(flat, x, 1)
      push(flat, x - 1, 1)
    end
  end
  return outline(flat)
end

--- A two-turn spiral arm of width 1: out along the outer edge, back along the inner one.
local function spiral(steps)
  local flat = {}
  local turns = 2.5
  local function at(t, off)
    local r = 2 + 0.6 * t - off
    push(flat, r * cos(t), r * sin(t))
  end
  for i = 0, steps do at(2 * pi * turns * i / steps, 0) end
  for i = steps, 0, -1 do at(2 * pi * turns * i / steps, 1) end
  return outline(flat)
end

--- A random simple polygon: star-shaped around its centre (angular gaps below pi), with random
--- scale, offset and winding; sometimes with collinear midpoints and duplicated points.
local function random_polygon(rng)
  local n = rng:int(3, 60)
  local scale = 10 ^ rng:range(-3, 4)
  local cx, cy = rng:range(-1e4, 1e4), rng:range(-1e4, 1e4)
  local gaps, total = {}, 0
  for i = 1, n do
    gaps[i] = rng:range(0.6, 1)
    total = total + gaps[i]
  end
  local xs, ys = {}, {}
  local a = rng:range(0, 2 * pi)
  local extras = rng:int(0, 3) -- 0: plain, 1: midpoints, 2: duplicates, 3: both
  for i = 1, n do
    local r = scale * rng:range(0.1, 1)
    xs[#xs + 1], ys[#ys + 1] = cx + r * cos(a), cy + r * sin(a)
    if (extras == 2 or extras == 3) and rng:next() < 0.2 then
      xs[#xs + 1], ys[#ys + 1] = xs[#xs], ys[#ys]
    end
    a = a + 2 * pi * gaps[i] / total
  end
  if extras == 1 or extras == 3 then
    local mx, my = {}, {}
    local m = #xs
    for i = 1, m do
      mx[#mx + 1], my[#my + 1] = xs[i], ys[i]
      local j = i % m + 1
      if rng:next() < 0.25 and (xs[i] ~= xs[j] or ys[i] ~= ys[j]) then
        mx[#mx + 1], my[#my + 1] = (xs[i] + xs[j]) / 2, (ys[i] + ys[j]) / 2
      end
    end
    xs, ys = mx, my
  end
  if rng:next() < 0.5 then return reversed(xs, ys, #xs) end
  return xs, ys, #xs
end

-- Large outlines: the shapes of the benchmark's "Concave construction" table, and more.

--- A random star: n vertices at sorted random angles (one in each of n equal sectors, so the
--- angular gaps stay below pi), each at a random radius in [0.2, 1].
local function random_star(rng, n)
  local xs, ys = {}, {}
  for i = 1, n do
    local a, r = 2 * pi * (i - 1 + rng:range(0.05, 0.95)) / n, rng:range(0.2, 1)
    xs[i], ys[i] = r * cos(a), r * sin(a)
  end
  return xs, ys, n
end

--- A band of width 1 whose both sides zigzag with amplitude 2 (n vertices, n even).
local function zigzag(n)
  local k = n / 2
  local xs, ys = {}, {}
  for i = 0, k - 1 do xs[#xs + 1], ys[#ys + 1] = i, (i % 2) * 2 end
  for i = k - 1, 0, -1 do xs[#xs + 1], ys[#ys + 1] = i, (i % 2) * 2 + 1 end
  return xs, ys, n
end

--- A circle of n vertices with radial noise a little larger than its sagitta: about half the
--- vertices reflex, every turn tiny.
local function near_convex(rng, n)
  local xs, ys = {}, {}
  local noise = 0.5 * (2 * pi / n) ^ 2
  for i = 1, n do
    local a, r = 2 * pi * (i - 1) / n, 1 + noise * rng:range(-1, 1)
    xs[i], ys[i] = r * cos(a), r * sin(a)
  end
  return xs, ys, n
end

--- The outline turned by angle a, scaled by f and moved by (dx, dy).
local function placed(xs, ys, n, a, f, dx, dy)
  local c, s = cos(a) * f, sin(a) * f
  local px, py = {}, {}
  for i = 1, n do px[i], py[i] = c * xs[i] - s * ys[i] + dx, s * xs[i] + c * ys[i] + dy end
  return px, py, n
end

local atan2 = math.atan2 or math.atan -- luacheck: ignore 143

--- A linear-time check for large outlines (check_pieces compares every piece with every
--- edge): every piece strictly convex (a strict left turn at every vertex, in the coordinates
--- as returned, turning once around in all), every piece vertex an input vertex, the pieces'
--- areas adding up to the outline's within a relative 1e-9, and at most 2r + 1 pieces for r
--- reflex vertices. Returns true, or false and what is wrong.
local function check_large(xs, ys, n, pieces)
  if type(pieces) ~= 'table' or #pieces == 0 then return false, 'no pieces' end
  local input = {}
  for i = 1, n do
    local row = input[xs[i]] or {}
    input[xs[i]] = row
    row[ys[i]] = true
  end
  local x0, y0 = xs[1], ys[1]
  local ox, oy = {}, {}
  for i = 1, n do ox[i], oy[i] = xs[i] - x0, ys[i] - y0 end
  local total = abs(signed_area(ox, oy, n))
  local sum = 0
  for k, piece in ipairs(pieces) do
    local m = #piece / 2
    if #piece % 2 ~= 0 or m < 3 then return false, ('piece %d has %d coordinates'):format(k, #piece) end
    local px, py = {}, {}
    for i = 1, m do
      local x, y = piece[2 * i - 1], piece[2 * i]
      if not (input[x] and input[x][y]) then
        return false, ('piece %d vertex %d (%.17g, %.17g) is not an input vertex'):format(k, i, x, y)
      end
      px[i], py[i] = x - x0, y - y0
    end
    local winding = 0
    for i = 1, m do
      local j, l = i % m + 1, (i + 1) % m + 1
      local t = turn(piece[2 * i - 1], piece[2 * i], piece[2 * j - 1], piece[2 * j], piece[2 * l - 1], piece[2 * l])
      if t <= 0 or t ~= t then
        return false, ('piece %d is not strictly convex at vertex %d (turn %.17g)'):format(k, j, t)
      end
      local ux, uy, vx, vy = px[j] - px[i], py[j] - py[i], px[l] - px[j], py[l] - py[j]
      winding = winding + atan2(ux * vy - uy * vx, ux * vx + uy * vy)
    end
    if abs(winding - 2 * pi) > 1e-6 then
      return false, ('piece %d turns %.17g times around'):format(k, winding / (2 * pi))
    end
    sum = sum + signed_area(px, py, m)
  end
  if abs(sum - total) > 1e-9 * total or sum ~= sum then
    return false, ('pieces cover area %.17g, outline has %.17g'):format(sum, total)
  end
  local r = reflex_count(xs, ys, n)
  if #pieces > 2 * r + 1 then return false, ('%d pieces for %d reflex vertices'):format(#pieces, r) end
  return true
end

--- Distance between the segments a-b and c-d (0 where they cross).
local function segment_gap(ax, ay, bx, by, cx, cy, dx, dy)
  local c1, c2 = turn(ax, ay, bx, by, cx, cy), turn(ax, ay, bx, by, dx, dy)
  local c3, c4 = turn(cx, cy, dx, dy, ax, ay), turn(cx, cy, dx, dy, bx, by)
  if (c1 > 0 and c2 < 0 or c1 < 0 and c2 > 0) and (c3 > 0 and c4 < 0 or c3 < 0 and c4 > 0) then return 0 end
  return sqrt(min(seg_dist2(cx, cy, ax, ay, bx, by), seg_dist2(dx, dy, ax, ay, bx, by),
    seg_dist2(ax, ay, cx, cy, dx, dy), seg_dist2(bx, by, cx, cy, dx, dy)))
end

--- Distance between edges i and j of an outline (edge k runs from vertex k to k % n + 1).
local function edge_distance(xs, ys, n, i, j)
  local i2, j2 = i % n + 1, j % n + 1
  return segment_gap(xs[i], ys[i], xs[i2], ys[i2], xs[j], ys[j], xs[j2], ys[j2])
end

--- Smallest distance between two non-adjacent edges of an outline, by trying every pair.
local function closest_edges(xs, ys, n)
  local best = math.huge
  for i = 1, n - 2 do
    for j = i + 2, i == 1 and n - 1 or n do best = min(best, edge_distance(xs, ys, n, i, j)) end
  end
  return best
end

describe('strike.geometry.decompose', function()
  describe('decompose', function()
    it('splits an L into 2 pieces, in either winding', function()
      local xs, ys, n = outline({ 0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2 })
      assert.equals(2, #decompose_ok(xs, ys, n))
      assert.equals(2, #decompose_ok(reversed(xs, ys, n)))
      assert.equals(2, #decompose_ok(xs, ys, 12 / 2)) -- a float count (n / 2 on Lua 5.3+)
    end)

    it('splits a U into 3 pieces, in either winding', function()
      local xs, ys, n = outline({ 0, 0, 3, 0, 3, 2, 2, 2, 2, 1, 1, 1, 1, 2, 0, 2 })
      assert.equals(3, #decompose_ok(xs, ys, n))
      assert.equals(3, #decompose_ok(reversed(xs, ys, n)))
    end)

    it('splits a chevron into 2 pieces and an arrow into at most 3', function()
      assert.equals(2, #decompose_ok(outline({ 0, 0, 2, 1, 0, 2, 1, 1 })))
      local pieces = decompose_ok(outline({ 0, 1, 3, 1, 3, 0, 5, 2, 3, 4, 3, 3, 0, 3 }))
      assert.is_true(#pieces <= 3)
    end)

    it('splits a comb with 6 teeth into 7 pieces', function()
      local xs, ys, n = comb(6)
      assert.equals(7, #decompose_ok(xs, ys, n))
      assert.equals(7, #decompose_ok(reversed(xs, ys, n)))
    end)

    it('decomposes a spiral', function()
      local xs, ys, n = spiral(30)
      assert.is_true(n >= 20)
      local pieces = decompose_ok(xs, ys, n)
      assert.is_true(#pieces <= 2 * reflex_count(xs, ys, n) + 1)
    end)

    it('decomposes 5- and 12-point stars', function()
      local xs, ys, n = star(5, 1, 0.4)
      local pieces = decompose_ok(xs, ys, n)
      assert.is_true(#pieces >= 3 and #pieces <= 2 * 5 + 1)
      xs, ys, n = star(12, 3, 2)
      pieces = decompose_ok(xs, ys, n)
      assert.is_true(#pieces >= 7 and #pieces <= 2 * 12 + 1)
    end)

    it('returns a convex outline as one counter-clockwise piece', function()
      local pieces = decompose_ok(outline({ 0, 0, 1, 0, 1, 1, 0, 1 }))
      assert.same({ { 0, 0, 1, 0, 1, 1, 0, 1 } }, pieces)
      pieces = decompose_ok(outline({ 0, 0, 0, 1, 1, 1, 1, 0 }))
      assert.equals(1, #pieces)
      assert.equals(8, #pieces[1])
      local flat = {}
      for i = 0, 19 do
        push(flat, 5 + cos(2 * pi * i / 20), -3 + sin(2 * pi * i / 20))
      end
      pieces = decompose_ok(outline(flat))
      assert.equals(1, #pieces)
      assert.equals(40, #pieces[1])
    end)

    it('works at any scale and offset', function()
      local l = { 0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2 }
      for _, t in ipairs({ { 1e150, 0 }, { 1e-100, 0 }, { 1e-6, 1e6 }, { 1e-3, -1e4 } }) do
        local flat = {}
        for i = 1, #l do flat[i] = l[i] * t[1] + t[2] end
        assert.equals(2, #decompose_ok(outline(flat)))
      end
    end)

    it('keeps a very sharp corner', function()
      assert.equals(1, #decompose_ok(outline({ 0, 0, 10, 0, 0, 1e-6 })))
      -- a thin spike on a square: the spike, the square and a sliver under the spike's foot
      assert.equals(3, #decompose_ok(outline({ 0, 0, 2, 0, 2, 2, 1, 2, 1.001, 5, 1, 2.001, 0, 2 })))
    end)

    it('drops collinear and duplicated points', function()
      local xs, ys, n = outline({ 0, 0, 1, 0, 2, 0, 2, 0, 2, 2, 0, 2, 0, 0 })
      local pieces = decompose_ok(xs, ys, n)
      assert.equals(1, #pieces)
      assert.same({ 0, 0, 2, 0, 2, 2, 0, 2 }, pieces[1])
      -- an L with a collinear point on its long edge and a repeated reflex corner
      pieces = decompose_ok(outline({ 0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 1, 1, 1, 2, 0, 2 }))
      assert.equals(2, #pieces)
    end)

    it('decomposes a 200-vertex star', function()
      local rng = PRNG.new(7)
      local flat = {}
      for i = 0, 199 do
        local r = rng:range(0.2, 1)
        push(flat, r * cos(2 * pi * i / 200), r * sin(2 * pi * i / 200))
      end
      local xs, ys, n = outline(flat)
      local pieces = decompose_ok(xs, ys, n)
      assert.is_true(#pieces <= 2 * reflex_count(xs, ys, n) + 1)
    end)

    it('tiles random simple polygons exactly (property)', function()
      local seed = PRNG.seedFromEnv(12345)
      local rng = PRNG.new(seed)
      for i = 1, 200 do
        local xs, ys, n = random_polygon(rng)
        local pieces, err = decompose.decompose(xs, ys, n)
        local ok, msg = pieces ~= nil, err
        if ok then ok, msg = check_pieces(xs, ys, n, pieces) end
        if ok and #pieces > 2 * reflex_count(xs, ys, n) + 1 then
          ok, msg = false, ('%d pieces for %d reflex vertices'):format(#pieces, reflex_count(xs, ys, n))
        end
        assert(ok, ('seed %s case %d: %s'):format(tostring(seed), i, tostring(msg)))
      end
    end)

    it('tiles large outlines: a 10,000-vertex random star; a comb, zigzag, spiral and near-circle', function()
      -- No timing here (bench/run.lua times Concave construction up to 10,000 vertices): this
      -- guards the results at sizes where the old quadratic code would have been too slow to
      -- test. The other shapes have 2,000 vertices, to keep the suite quick on every VM.
      local seed = PRNG.seedFromEnv(4242)
      local rng = PRNG.new(seed)
      local cases = {
        { 'random star', 10000, { random_star(rng, 10000) } },
        { 'comb', 2000, { comb(500) } },
        { 'zigzag', 2000, { zigzag(2000) } },
        { 'spiral', 2000, { spiral(999) } },
        { 'nearly convex', 2000, { near_convex(rng, 2000) } },
      }
      for _, case in ipairs(cases) do
        local xs, ys, n = case[3][1], case[3][2], case[3][3]
        assert.equals(case[2], n)
        local pieces, err = decompose.decompose(xs, ys, n)
        local ok, msg = pieces ~= nil, err
        if ok then ok, msg = check_large(xs, ys, n, pieces) end
        assert(ok, ('seed %s, %s: %s'):format(tostring(seed), case[1], tostring(msg)))
      end
    end)

    it('tiles turned, scaled and moved random stars, combs, zigzags, spirals and near-circles (property)', function()
      local seed = PRNG.seedFromEnv(777)
      local rng = PRNG.new(seed)
      for i = 1, 40 do
        local kind = (i - 1) % 5 + 1
        local xs, ys, n
        if kind == 1 then xs, ys, n = random_star(rng, rng:int(20, 300))
        elseif kind == 2 then xs, ys, n = comb(rng:int(2, 60))
        elseif kind == 3 then xs, ys, n = zigzag(2 * rng:int(4, 100))
        elseif kind == 4 then xs, ys, n = spiral(rng:int(10, 80))
        else xs, ys, n = near_convex(rng, rng:int(20, 300)) end
        -- (a comb turned by any angle has nearly collinear rows of corners, at the collinearity
        -- tolerance: its base piece can then fail as numerical degeneracy, 0.5% of the time,
        -- as with the ear clipping before; combs get exact quarter turns)
        local angle = rng:range(0, 2 * pi)
        if kind == 2 then
          for _ = 1, rng:int(0, 3) do
            for k = 1, n do xs[k], ys[k] = -ys[k], xs[k] end
          end
          angle = 0
        end
        xs, ys, n = placed(xs, ys, n, angle, 10 ^ rng:range(-3, 3), rng:range(-1e3, 1e3), rng:range(-1e3, 1e3))
        if rng:next() < 0.5 then xs, ys, n = reversed(xs, ys, n) end
        local pieces, err = decompose.decompose(xs, ys, n)
        local ok, msg = pieces ~= nil, err
        if ok then ok, msg = check_pieces(xs, ys, n, pieces) end
        if ok and #pieces > 2 * reflex_count(xs, ys, n) + 1 then
          ok, msg = false, ('%d pieces for %d reflex vertices'):format(#pieces, reflex_count(xs, ys, n))
        end
        assert(ok, ('seed %s case %d (kind %d, %d vertices): %s'):format(tostring(seed), i, kind, n, tostring(msg)))
      end
    end)
  end)

  describe('the tiling checker', function()
    local xs, ys, n = outline({ 0, 0, 3, 0, 3, 2, 2, 2, 2, 1, 1, 1, 1, 2, 0, 2 }) -- a U, area 5

    it('accepts an exact tiling', function()
      assert.is_true((check_pieces(xs, ys, n, {
        { 0, 0, 3, 0, 3, 1, 0, 1 }, { 0, 1, 1, 1, 1, 2, 0, 2 }, { 2, 1, 3, 1, 3, 2, 2, 2 },
      })))
    end)

    it('catches a missing piece, an overlap, a clockwise piece and a piece leaving the outline', function()
      local cases = {
        { { 0, 0, 3, 0, 3, 1, 0, 1 }, { 0, 1, 1, 1, 1, 2, 0, 2 } },
        { { 0, 0, 3, 0, 3, 1, 0, 1 }, { 0, 0.5, 1, 0.5, 1, 2, 0, 2 }, { 2, 1, 3, 1, 3, 2, 2, 2 } },
        { { 0, 0, 3, 0, 3, 1, 0, 1 }, { 0, 1, 0, 2, 1, 2, 1, 1 }, { 2, 1, 3, 1, 3, 2, 2, 2 } },
        { { 0, 0, 3, 0, 3, 1.8, 0, 1.8 } },
        { { 0, 0, 3, 0, 3, 2, 0, 2 } },
      }
      for k, pieces in ipairs(cases) do
        local ok, msg = check_pieces(xs, ys, n, pieces)
        assert.is_false(ok, 'case ' .. k)
        assert.is_string(msg)
      end
    end)
  end)

  describe('rejects', function()
    local function rejects(pattern, flat)
      local xs, ys, n = outline(flat)
      local pieces, err = decompose.decompose(xs, ys, n)
      assert.is_nil(pieces)
      assert.is_string(err)
      assert.matches(pattern, err)
    end

    it('exactly the outlines with two non-adjacent edges closer than the tolerance (property)', function()
      -- Near misses of four kinds, at gaps from -1e-11 to 1e-9 of the size:
      --  1. a vertex of a random star pulled to a random point of another edge and moved off it
      --     (across the edge or not), or pulled next to the edge's end and off to its side;
      --     sometimes squashed along x, making edges nearly parallel to y;
      --  2. a ring whose two ends come close (parallel, or meeting at a corner), turned at random;
      --  3. two wedge tips pointing at each other along a diagonal (neither tip lies within the
      --     x or the y span of the other's edges: only the close-vertex grid sees them);
      --  4. a wedge tip pointing at an edge along y from beside its span along x (only the sweep
      --     along y sees it; transposed, only the sweep along x).
      -- The tolerance is DIST_EPS = 1e-12 of the size rounded to a power of two, between 1e-12
      -- and 2e-12 of the extent: below 0.5e-12 an outline must be rejected, naming two edges
      -- that close; above 4e-12 it must not be called self-intersecting. Between, nothing is
      -- asserted. (Every pair of edges is measured here, in the outline's own coordinates.)
      local seed = PRNG.seedFromEnv(31337)
      local rng = PRNG.new(seed)
      local gaps = { -1e-11, 0, 1e-15, 1e-14, 1e-13, 2e-13, 5e-13, 1e-12, 3e-12, 1e-11, 1e-10, 1e-9 }
      local near, far = 0, 0
      for i = 1, 400 do
        local kind, g = (i - 1) % 4 + 1, gaps[rng:int(1, #gaps)]
        local xs, ys, n
        if kind == 1 then
          xs, ys, n = random_star(rng, rng:int(5, 40))
          -- edge e from vertex e to e2; v is none of e - 1, e, e2, e2 + 1 (a vertex moved next to
          -- its own neighbour would be dropped as a duplicate)
          local e = rng:int(1, n)
          local e2 = e % n + 1
          local v = (e2 + rng:int(2, n - 3) - 1) % n + 1
          local ex, ey = xs[e2] - xs[e], ys[e2] - ys[e]
          g = 2 * abs(g) -- the extent is about 2
          if rng:next() < 0.5 then -- to a random point of the edge, then off it in any direction
            local t, a = rng:next() < 0.2 and rng:int(0, 1) or rng:next(), rng:range(0, 2 * pi)
            xs[v], ys[v] = xs[e] + t * ex + g * cos(a), ys[e] + t * ey + g * sin(a)
          else -- to within 1e-13 to 1e-6 of its end e2, then off to either side
            local t, o = 1 - 10 ^ rng:range(-13, -6), rng:range(-g, g) / sqrt(ex * ex + ey * ey)
            xs[v], ys[v] = xs[e] + t * ex - o * ey, ys[e] + t * ey + o * ex
          end
          if rng:next() < 0.3 then
            local f = 10 ^ rng:range(-9, -3)
            for k = 1, n do xs[k] = xs[k] * f end
          end
        elseif kind == 2 then
          -- from its end (0.5, 0)-(1, 0) counter-clockwise round to its other end, 2g below
          local k, tilt = rng:int(3, 12), rng:int(0, 2)
          local flat = { 0.5, 0, 1, 0 }
          for j = 1, k - 1 do push(flat, cos(2 * pi * j / k), sin(2 * pi * j / k)) end
          push(flat, 1, -2 * g - (tilt == 1 and 0.01 or 0))
          push(flat, 0.5, -2 * g - (tilt == 2 and 0.01 or 0))
          for j = k - 1, 1, -1 do push(flat, 0.5 * cos(2 * pi * j / k), 0.5 * sin(2 * pi * j / k)) end
          xs, ys, n = outline(flat)
          xs, ys, n = placed(xs, ys, n, rng:range(0, 2 * pi), 1, rng:range(-10, 10), rng:range(-10, 10))
        elseif kind == 3 then
          -- a loop pinched where the tip (0, 0), opening down and right, meets the tip (-d, d)
          local d = 4 * g
          xs, ys, n = outline({ 0, 0, 0.2, -1, 0.2, -2, -3, -2, -3, 0.2 + d, -1 - d, 0.2 + d, -d, d,
            -0.2 - d, 1 + d, -0.2 - d, 2, 3, 2, 3, -0.2, 1, -0.2 })
        else
          -- a notch x in (-1, 0), y < 1 whose right side is the edge (0, 1)-(0, -1); a tip
          -- from its left side points at it, d short of it
          local d = 4 * g
          xs, ys, n = outline({ 0, -1, 2, -1, 2, 2, -2, 2, -2, -1, -1, -1, -1, -0.3, -d, 0, -1, 0.3, -1, 1,
            0, 1 })
        end
        if kind >= 3 then -- moved and scaled, not turned (the tips and the edge stay along the axes)
          local f, dx, dy = 10 ^ rng:range(-2, 2), rng:range(-10, 10), rng:range(-10, 10)
          for k = 1, n do xs[k], ys[k] = xs[k] * f + dx, ys[k] * f + dy end
        end
        if rng:next() < 0.5 then xs, ys = ys, xs end
        local x0, x1, y0, y1 = math.huge, -math.huge, math.huge, -math.huge
        for k = 1, n do x0, x1, y0, y1 = min(x0, xs[k]), max(x1, xs[k]), min(y0, ys[k]), max(y1, ys[k]) end
        local extent = max(x1 - x0, y1 - y0)
        local d = closest_edges(xs, ys, n)
        local pieces, err = decompose.decompose(xs, ys, n)
        local case = ('seed %s case %d (kind %d, closest edges %.3g of the extent): '):format(tostring(seed), i,
          kind, d / extent)
        if d <= 0.5e-12 * extent then
          near = near + 1
          -- (a vertex pulled onto a neighbour's end can make a spike instead)
          if not tostring(err):match('^outline folds back on itself') then
            local a, b = tostring(err):match('^outline intersects itself %(edges (%d+) and (%d+)%)$')
            assert(a, case .. 'got ' .. tostring(err))
            a, b = tonumber(a), tonumber(b)
            assert(a < b and b - a ~= 1 and not (a == 1 and b == n), case .. 'adjacent edges named: ' .. err)
            assert(edge_distance(xs, ys, n, a, b) <= 2.01e-12 * extent, case .. 'edges named too far apart: ' .. err)
          end
        elseif d >= 4e-12 * extent then
          far = far + 1
          assert(not tostring(err):match('intersects itself'), case .. 'got ' .. tostring(err))
          if pieces then
            local ok, msg = check_pieces(xs, ys, n, pieces)
            assert(ok, case .. tostring(msg))
          end
        end
      end
      assert(near >= 100 and far >= 40, ('seed %s: %d near and %d far cases'):format(tostring(seed), near, far))
    end)

    it('a crossing or a touch between any two edges, at 5 to 34 vertices (every pair tested up to 32)', function()
      -- (decompose tests every pair of edges of an outline of up to 32 vertices before its
      -- sweeps, which then run only when a pair meets: the pairs of every place along the
      -- outline, on both sides of that count, must be found)
      for _, m in ipairs({ 5, 6, 9, 31, 32, 33, 34 }) do
        local function gon(k)
          local a = 2 * pi * (k - 1) / m
          return cos(a), sin(a)
        end
        for k = 1, m do
          -- vertices k and k + 1 of a regular m-gon swapped: edges k - 1 and k + 1 cross
          local flat = {}
          for i = 1, m do
            local j = i == k and k % m + 1 or i == k % m + 1 and k or i
            push(flat, gon(j))
          end
          local a, b = (k + m - 2) % m + 1, k % m + 1
          if a > b then a, b = b, a end
          rejects(('^outline intersects itself %%(edges %d and %d%%)$'):format(a, b), flat)
          -- vertex k moved onto the middle of the edge j across from it: the edges k - 1 and k
          -- touch edge j (either pair may be named)
          if m >= 6 then
            local j = (k + floor(m / 2) - 1) % m + 1
            local jx, jy = gon(j)
            local kx, ky = gon(j % m + 1)
            flat = {}
            for i = 1, m do
              if i == k then push(flat, (jx + kx) / 2, (jy + ky) / 2) else push(flat, gon(i)) end
            end
            local xs, ys, n = outline(flat)
            local pieces, err = decompose.decompose(xs, ys, n)
            local e1, e2 = tostring(err):match('^outline intersects itself %(edges (%d+) and (%d+)%)$')
            assert(not pieces and e1, ('%d-gon, vertex %d on edge %d: got %s'):format(m, k, j, tostring(err)))
            local named = { [tonumber(e1)] = true, [tonumber(e2)] = true }
            assert(named[j] and (named[(k + m - 2) % m + 1] or named[k]),
              ('%d-gon, vertex %d on edge %d: named edges %s and %s'):format(m, k, j, e1, e2))
          end
        end
      end
    end)

    it('a bow-tie', function()
      rejects('^outline intersects itself %(edges 1 and 3%)$', { 0, 0, 1, 1, 1, 0, 0, 1 })
    end)

    it('an outline touching itself', function()
      -- vertex 5 lies on edge 1
      rejects('^outline intersects itself', { 0, 0, 4, 0, 4, 2, 3, 2, 2, 0, 1, 2, 0, 2 })
    end)

    it('a spike folding back onto its own edge', function()
      rejects('^outline folds back on itself at vertex 5', { 0, 0, 2, 0, 2, 2, 1, 2, 1, 3, 1, 2.5, 0, 2 })
    end)

    it('fewer than 3 distinct points', function()
      rejects('^needs at least 3 distinct points, got 2$', { 0, 0, 1, 1, 0, 0, 1, 1 })
      rejects('^needs at least 3 distinct points, got 2$', { 0, 0, 1, 1 })
      rejects('^needs at least 3 distinct points, got 1$', { 3, 4, 3, 4, 3, 4, 3, 4 })
    end)

    it('collinear points', function()
      rejects('^outline has zero area$', { 0, 0, 1, 0, 2, 0, 3, 0 })
      rejects('^outline has zero area$', { 0, 0, 1, 1, 2, 2, 1, 1 })
    end)

    it('points closer than the tolerance', function()
      rejects('^outline has zero area$', { 0, 0, 1, 0, 1, 1e-14, 0, 1e-14 })
    end)

    it('coordinates too large or an outline too small', function()
      rejects('^coordinates too large$', { 0, 0, 1e200, 0, 1e200, 1e200, 0, 1e200 })
      rejects('^coordinates too large$', { -1e300, 0, 1e300, 0, 0, 1e300 })
      rejects('^outline too small$', { 0, 0, 1e-150, 0, 1e-150, 1e-150, 0, 1e-150 })
    end)
  end)
end)
