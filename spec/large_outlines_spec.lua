-- Large outlines: S.trikers.Concave of a regular star with thousands of spikes (the worst case
-- of the benchmark's Concave construction: a piece of thousands of vertices at its centre,
-- every face of it a seam) and S.hapes.ConvexPolygon from thousands of points. The checks are
-- oracles written here from the star's and the polygon's own description, never from
-- strike's answers; no timing (bench/run.lua times Concave construction). Reproduce a failure
-- with STRIKE_SEED=<seed> (any VM); the message names the seed and the case.
local S = require('strike')
local PRNG = require('spec.helpers.prng')
local budget = require('spec.helpers.budget')

local T, H = S.trikers, S.hapes
local abs, sqrt, cos, sin, pi, floor, huge = math.abs, math.sqrt, math.cos, math.sin, math.pi, math.floor, math.huge
local atan2 = math.atan2 or math.atan -- luacheck: ignore 143

local SEED = PRNG.seedFromEnv(20261127)

-- A regular star --------------------------------------------------------------------------

-- k spikes: vertex j (0 .. 2k - 1, counter-clockwise) at angle pi j / k, radius 1 for even j
-- (the tips), rin for odd j; then turned by a, scaled by f and moved by (dx, dy).
local function newStar(k, rin, a, f, dx, dy)
  local st = { k = k, n = 2 * k, rin = rin, a = a, f = f, dx = dx, dy = dy, x = {}, y = {} }
  local c, s = cos(a) * f, sin(a) * f
  for j = 0, 2 * k - 1 do
    local r = j % 2 == 0 and 1 or rin
    local u, v = r * cos(pi * j / k), r * sin(pi * j / k)
    st.x[j], st.y[j] = c * u - s * v + dx, s * u + c * v + dy
  end
  return st
end

-- The star's own frame: (x, y) turned, scaled and moved back.
local function toStar(st, x, y)
  local c, s = cos(st.a), sin(st.a)
  x, y = (x - st.dx) / st.f, (y - st.dy) / st.f
  return c * x + s * y, -s * x + c * y
end

-- The outline as Concave takes it, counter-clockwise or (reversed) clockwise.
local function flat(st, clockwise)
  local out = {}
  for i = 0, st.n - 1 do
    local j = clockwise and (st.n - i) % st.n or i
    out[2 * i + 1], out[2 * i + 2] = st.x[j], st.y[j]
  end
  return out
end

-- The star vertex at (x, y) (within 1e-9 of the star's size), from its angle; or nil.
local function vertexAt(st, x, y)
  local u, v = toStar(st, x, y)
  local j = floor(atan2(v, u) * st.k / pi + 0.5) % st.n
  if abs(st.x[j] - x) + abs(st.y[j] - y) <= 1e-9 * st.f then return j end
  return nil
end

-- In the star's frame: is (u, v) inside (1), outside (-1), or within `margin` of the outline
-- (0)? The point lies in the sector of edge j (from vertex j to j + 1): inside when it is on
-- the left of that edge.
local function starSide(st, u, v, margin)
  local j = floor(atan2(v, u) * st.k / pi) % st.n
  local j2 = (j + 1) % st.n
  local r1, r2 = j % 2 == 0 and 1 or st.rin, j2 % 2 == 0 and 1 or st.rin
  local ax, ay = r1 * cos(pi * j / st.k), r1 * sin(pi * j / st.k)
  local bx, by = r2 * cos(pi * (j + 1) / st.k), r2 * sin(pi * (j + 1) / st.k)
  local ex, ey = bx - ax, by - ay
  local d = (ex * (v - ay) - ey * (u - ax)) / sqrt(ex * ex + ey * ey)
  if abs(d) <= margin then return 0 end
  return d > 0 and 1 or -1
end

-- The pieces of a Concave of the star tile it, and its seams are its cuts. Returns nil, or
-- what is wrong. Each piece: strictly convex and counter-clockwise, every vertex a star vertex
-- (so that pieces hold the caller's points), every face an outline edge (vertex j to j + 1)
-- and then no seam, or a cut and then wholly a seam. The pieces: at most 2k + 1 of them
-- (Hertel-Mehlhorn's bound for k reflex corners), their areas adding up to the star's, and
-- random points away from the outline inside exactly one piece when inside the star, in none
-- when outside, with containsPoint agreeing on some. (Two tips can share a piece: nearly opposite
-- ones, whose chord runs through the middle.)
local function checkStar(st, c, rng)
  local pieces = { c:unpack() }
  local tol = 1e-9 * st.f
  if #pieces > 2 * st.k + 1 then
    return ('%d pieces for %d spikes'):format(#pieces, st.k)
  end
  local sum, boxes, largest = 0, {}, 0
  for p, piece in ipairs(pieces) do
    local m = piece:getVertexCount()
    if m > largest then largest = m end
    local px, py, id = {}, {}, {}
    local x0, y0, x1, y1 = huge, huge, -huge, -huge
    for i = 1, m do
      px[i], py[i] = piece:getVertex(i)
      id[i] = vertexAt(st, px[i], py[i])
      if not id[i] then return ('piece %d: vertex %d is not a star vertex'):format(p, i) end
      x0, y0 = math.min(x0, px[i]), math.min(y0, py[i])
      x1, y1 = math.max(x1, px[i]), math.max(y1, py[i])
    end
    local area = 0
    for i = 1, m do
      local j, l = i % m + 1, (i + 1) % m + 1
      local turn = (px[j] - px[i]) * (py[l] - py[j]) - (py[j] - py[i]) * (px[l] - px[j])
      if turn <= 0 or turn ~= turn then return ('piece %d: not strictly convex at vertex %d'):format(p, j) end
      area = area + (px[i] - st.dx) * (py[j] - st.dy) - (px[j] - st.dx) * (py[i] - st.dy)
      local seam = piece._seams and piece._seams[i]
      if id[j] == (id[i] + 1) % st.n then
        if seam then return ('piece %d: outline face %d is marked a seam'):format(p, i) end
      elseif seam ~= true then
        return ('piece %d: face %d is a cut, its seam is %s'):format(p, i, tostring(seam))
      end
    end
    sum = sum + area / 2
    boxes[p] = { x0, y0, x1, y1, px, py, m }
  end
  local want = st.k * st.rin * sin(pi / st.k) * st.f * st.f -- 2k triangles (centre, j, j + 1)
  if abs(sum - want) > 1e-9 * want then return ('pieces cover %.17g, the star %.17g'):format(sum, want) end
  -- the pieces by the cells of a 32 x 32 grid that their boxes overlap
  local gx0, gy0, gx1, gy1 = huge, huge, -huge, -huge
  for p = 1, #boxes do
    local b = boxes[p]
    gx0, gy0, gx1, gy1 = math.min(gx0, b[1]), math.min(gy0, b[2]), math.max(gx1, b[3]), math.max(gy1, b[4])
  end
  local cw, ch, grid = (gx1 - gx0) / 32, (gy1 - gy0) / 32, {}
  local function cell(x, y)
    return math.max(0, math.min(31, floor((x - gx0) / cw))), math.max(0, math.min(31, floor((y - gy0) / ch)))
  end
  for p = 1, #boxes do
    local b = boxes[p]
    local i0, j0 = cell(b[1] - tol, b[2] - tol)
    local i1, j1 = cell(b[3] + tol, b[4] + tol)
    for i = i0, i1 do
      for j = j0, j1 do
        local list = grid[32 * j + i] or {}
        grid[32 * j + i] = list
        list[#list + 1] = p
      end
    end
  end
  for case = 1, 200 do
    local rho, theta = 1.05 * sqrt(rng:next()), rng:range(0, 2 * pi)
    local u, v = rho * cos(theta), rho * sin(theta)
    local side = starSide(st, u, v, 1e-6)
    if side ~= 0 then
      local cs, sn = cos(st.a) * st.f, sin(st.a) * st.f
      local x, y = cs * u - sn * v + st.dx, sn * u + cs * v + st.dy
      local holders, edge = 0, false
      local ci, cj = cell(x, y)
      local list = grid[32 * cj + ci] or {}
      for q = 1, #list do
        local b = boxes[list[q]]
        if x >= b[1] - tol and x <= b[3] + tol and y >= b[2] - tol and y <= b[4] + tol then
          local px, py, m, d = b[5], b[6], b[7], huge
          for i = 1, m do
            local j = i % m + 1
            local ex, ey = px[j] - px[i], py[j] - py[i]
            d = math.min(d, (ex * (y - py[i]) - ey * (x - px[i])) / sqrt(ex * ex + ey * ey))
          end
          if d > tol then holders = holders + 1 elseif d >= -tol then edge = true end
        end
      end
      if not edge then -- (a point on a cut is in two pieces' closures: left out)
        if holders ~= (side > 0 and 1 or 0) then
          return ('point %d (%.17g, %.17g, %s the star) is in %d pieces'):format(case, x, y,
            side > 0 and 'inside' or 'outside', holders)
        end
        local inside = side > 0
        -- (containsPoint on the first 40: it walks the large piece's faces, a few ms a point)
        if case <= 40 and c:containsPoint(x, y) ~= inside then
          return ('point %d (%.17g, %.17g): containsPoint says %s'):format(case, x, y, tostring(not inside))
        end
      end
    end
  end
  return nil, largest
end

describe('S.trikers.Concave of a regular star', function()
  it('tiles the 5,000-spike star of the benchmark, its seams exactly its cuts', function()
    local st = newStar(5000, 0.5, 0, 1, 0, 0)
    local c = T.Concave(flat(st))
    local err, largest = checkStar(st, c, PRNG.new(SEED))
    assert(not err, ('seed %d: %s'):format(SEED, tostring(err)))
    -- (what makes this the worst case, and what this spec is for: a piece of thousands of
    -- vertices, every face of it a seam, built as one ConvexPolygon)
    assert.is_true(largest >= 1000, 'no large piece: ' .. largest .. ' vertices at most')
  end)

  it('tiles turned, scaled, moved stars of 100 to 1,000 spikes in either winding (property)', function()
    local rng = PRNG.new(SEED + 1)
    budget.loop(8, function(case)
      local k, rin = rng:int(100, 1000), rng:range(0.3, 0.95)
      local f = 10 ^ rng:range(-2, 3)
      local st = newStar(k, rin, rng:range(0, 2 * pi), f, rng:range(-1e3, 1e3), rng:range(-1e3, 1e3))
      local clockwise = rng:next() < 0.5
      local where = ('seed %d case %d (%d spikes, inner radius %.17g, %s)'):format(SEED + 1, case, k, rin,
        clockwise and 'clockwise' or 'counter-clockwise')
      local ok, c = pcall(T.Concave, flat(st, clockwise))
      assert(ok, where .. ': ' .. tostring(c))
      local err = checkStar(st, c, rng)
      assert(not err, where .. ': ' .. tostring(err))
    end)
  end)
end)

describe('S.trikers.Concave of a polygon with a tooth on every face', function()
  it('has each face a seam under its tooth and a surface beside it (property)', function()
    -- a regular k-gon of radius f with, on each face, a rectangular tooth outwards on the face's
    -- middle (from 0.3 to 0.7 of it): each face of the k-gon is outline, cut, outline, and a
    -- piece holding the k-gon has k such faces, each with a seam part under its tooth
    local rng = PRNG.new(SEED + 4)
    budget.loop(4, function(case)
      local k, f = rng:int(150, 400), 10 ^ rng:range(-1, 2)
      local dx, dy, a0 = rng:range(-10, 10) * f, rng:range(-10, 10) * f, rng:range(0, 2 * pi)
      local px, py = {}, {}
      for j = 0, k do px[j], py[j] = dx + f * cos(a0 + 2 * pi * j / k), dy + f * sin(a0 + 2 * pi * j / k) end
      local v = {}
      for j = 0, k - 1 do
        local ex, ey = px[j + 1] - px[j], py[j + 1] - py[j]
        local hx, hy = 0.3 * ey, -0.3 * ex -- outwards (the k-gon is counter-clockwise)
        v[#v + 1], v[#v + 2] = px[j], py[j]
        for _, t in ipairs({ 0.3, 0.3, 0.7, 0.7 }) do v[#v + 1], v[#v + 2] = px[j] + t * ex, py[j] + t * ey end
        v[#v - 5], v[#v - 4] = v[#v - 5] + hx, v[#v - 4] + hy -- (the tooth's outer corners)
        v[#v - 3], v[#v - 2] = v[#v - 3] + hx, v[#v - 2] + hy
      end
      local where = ('seed %d case %d (%d faces)'):format(SEED + 4, case, k)
      local c = T.Concave(v)
      local most = 0 -- the most faces with seam parts on one piece
      for piece in c:elems() do
        local count = 0
        for _, seam in ipairs(piece._seams or {}) do
          if type(seam) == 'table' then count = count + 1 end
        end
        if count > most then most = count end
      end
      for j = 0, k - 1 do
        local ex, ey = px[j + 1] - px[j], py[j + 1] - py[j]
        local len = sqrt(ex * ex + ey * ey)
        for _, t in ipairs({ 0.1, 0.28, 0.32, 0.5, 0.68, 0.72, 0.9 }) do
          -- a ray from the centre through the face at t: it leaves at the face beside the tooth,
          -- and goes on into the tooth under it, where a point of the face is inside
          local x, y = px[j] + t * ex, py[j] + t * ey
          local ux, uy = x - dx, y - dy
          local dist = sqrt(ux * ux + uy * uy)
          local d = c:rayCast(dx, dy, ux / dist, uy / dist)
          local at = ('%s: face %d at %g'):format(where, j, t)
          if t > 0.3 and t < 0.7 then
            assert(c:containsPoint(x, y), ('%s: (%.17g, %.17g) is not inside'):format(at, x, y))
            assert(d and d > dist + 0.1 * len, ('%s: the ray stops at %s, not in the tooth beyond %.17g'):format(at,
              tostring(d), dist))
          else
            assert(d and abs(d - dist) <= 1e-9 * f, ('%s: the ray stops at %s, not at the face (%.17g)'):format(at,
              tostring(d), dist))
          end
        end
      end
      -- (what this case is for: a piece with many faces that are partly seams, 20 x 20 face pairs
      -- and more, where VertexShape:_seamsFrom sweeps instead of testing every pair)
      assert(most >= 20, ('%s: %d faces with seam parts on one piece at most'):format(where, most))
    end)
  end)
end)

describe('the seam parts of a face', function()
  it('come sorted by start, stably, however many (property)', function()
    -- (a comb's bar has a part under each tooth; they may arrive in any order, some with equal
    -- starts: the oracle is a plain stable sort of the records)
    local seamOf = require('strike.base.VertexShape')._seamOf
    local rng = PRNG.new(SEED + 5)
    budget.loop(40, function(case)
      local k = rng:int(2, 400)
      local parts, recs = {}, {}
      for j = 1, k do
        local a = rng:int(0, 3 * k) / (3 * k) -- (coarse: equal starts happen)
        local b = a + rng:range(0.001, 0.01)
        parts[2 * j - 1], parts[2 * j] = a, b
        recs[j] = { a, b }
      end
      for j = 2, k do -- (insertion: a record moves before those that start later only)
        local r, i = recs[j], j - 1
        while i >= 1 and recs[i][1] > r[1] do
          recs[i + 1] = recs[i]
          i = i - 1
        end
        recs[i + 1] = r
      end
      local got = seamOf(parts, 2 * k, 1, 1e-12)
      for j = 1, k do
        assert(got[2 * j - 1] == recs[j][1] and got[2 * j] == recs[j][2],
          ('seed %d case %d (%d parts): part %d is %.17g..%.17g, want %.17g..%.17g'):format(SEED + 5, case, k, j,
            got[2 * j - 1], got[2 * j], recs[j][1], recs[j][2]))
      end
    end)
  end)
end)

-- ConvexPolygon from many points -----------------------------------------------------------

-- k points on a circle at sorted random angles (gaps from 0.5 to 1 times the mean: every turn
-- far above the hull's collinearity tolerance), scaled and moved by up to its radius (further,
-- the rounding of the coordinates would reach the tolerance of an edge's midpoint, whose
-- distance to its edge is only that rounding).
local function circlePoints(rng, k)
  local f = 10 ^ rng:range(-2, 3)
  local dx, dy = rng:range(-f, f), rng:range(-f, f)
  local gaps, total = {}, 0
  for i = 1, k do
    gaps[i] = rng:range(0.5, 1)
    total = total + gaps[i]
  end
  local xs, ys, a = {}, {}, rng:range(0, 2 * pi)
  for i = 1, k do
    xs[i], ys[i] = dx + f * cos(a), dy + f * sin(a)
    a = a + 2 * pi * gaps[i] / total
  end
  return xs, ys, f, dx, dy
end

-- Does the polygon have exactly the vertices xs, ys (1..k), counter-clockwise from the first?
local function sameVertices(poly, xs, ys, k, tol)
  if poly:getVertexCount() ~= k then return ('%d vertices, want %d'):format(poly:getVertexCount(), k) end
  for i = 1, k do
    local x, y = poly:getVertex(i)
    if abs(x - xs[i]) + abs(y - ys[i]) > tol then return ('vertex %d is off'):format(i) end
  end
  return nil
end

describe('S.hapes.ConvexPolygon from many points', function()
  it('keeps every vertex of thousands given in order, reversed, repeated or with midpoints', function()
    local rng = PRNG.new(SEED + 2)
    budget.loop(12, function(case)
      local k = rng:int(500, 3000)
      local xs, ys, f = circlePoints(rng, k)
      local mode = (case - 1) % 4 -- in order; clockwise; repeated points; edge midpoints
      local start = rng:int(1, k)
      -- want: the vertices counter-clockwise from the first point given, whatever the winding
      local pts, want = {}, {}
      for i = 0, k - 1 do
        local j = (start - 1 + i) % k + 1
        want[i + 1] = j
        if mode == 1 then j = (start - 1 - i) % k + 1 end
        pts[#pts + 1], pts[#pts + 2] = xs[j], ys[j]
        if mode == 2 and rng:next() < 0.3 then pts[#pts + 1], pts[#pts + 2] = xs[j], ys[j] end
        if mode == 3 and rng:next() < 0.3 then
          local l = j % k + 1
          pts[#pts + 1], pts[#pts + 2] = (xs[j] + xs[l]) / 2, (ys[j] + ys[l]) / 2
        end
      end
      local wx, wy = {}, {}
      for i = 1, k do wx[i], wy[i] = xs[want[i]], ys[want[i]] end
      local where = ('seed %d case %d (%d points, mode %d)'):format(SEED + 2, case, k, mode)
      local ok, poly = pcall(H.ConvexPolygon, pts)
      assert(ok, where .. ': ' .. tostring(poly))
      local err = sameVertices(poly, wx, wy, k, 1e-9 * f)
      assert(not err, where .. ': ' .. tostring(err))
    end)
  end)

  it('names the first point inside the hull among thousands, in any order', function()
    local rng = PRNG.new(SEED + 3)
    budget.loop(12, function(case)
      local shuffled = case % 3 == 0
      local k = shuffled and rng:int(50, 300) or rng:int(500, 3000)
      local xs, ys, f, dx, dy = circlePoints(rng, k)
      local order = {}
      for i = 1, k do order[i] = i end
      if shuffled then
        for i = k, 2, -1 do
          local j = rng:int(1, i)
          order[i], order[j] = order[j], order[i]
        end
      end
      local pts = {}
      for i = 1, k do pts[2 * i - 1], pts[2 * i] = xs[order[i]], ys[order[i]] end
      -- one or two points well inside (radius 0.2 to 0.9), at random positions in the list
      for _ = 1, rng:int(1, 2) do
        local at, r, a = rng:int(1, #pts / 2 + 1), rng:range(0.2, 0.9), rng:range(0, 2 * pi)
        table.insert(pts, 2 * at - 1, dy + f * r * sin(a))
        table.insert(pts, 2 * at - 1, dx + f * r * cos(a))
      end
      -- the oracle: the first point well inside the polygon, i.e. nearer its centre than 0.95 of
      -- the radius (its points are on the circle; its edges, whose angular gaps are at most
      -- 4 pi / k, stay beyond cos(2 pi / k) > 0.99 of the radius; the inserted ones are within 0.9)
      local want
      for i = 1, #pts / 2 do
        local ux, uy = pts[2 * i - 1] - dx, pts[2 * i] - dy
        if sqrt(ux * ux + uy * uy) < 0.95 * f then
          want = i
          break
        end
      end
      local where = ('seed %d case %d (%d points%s)'):format(SEED + 3, case, k, shuffled and ', shuffled' or '')
      assert(want, where .. ': no point inside')
      local ok, err = pcall(H.ConvexPolygon, pts)
      assert(not ok, where .. ': accepted')
      local named = tonumber(tostring(err):match('concave polygon %(point (%d+),'))
      assert(named == want, ('%s: the error names point %s, want %d: %s'):format(where, tostring(named), want,
        tostring(err)))
    end)
  end)
end)
