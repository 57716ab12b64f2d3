-- Property specs for S.ite on compound MTVs, against an oracle written here that shares no
-- code with strike/collide: bodies are read through public accessors only (getVertices,
-- getRounding, getCentroid, getRadius), and every distance is a brute-force one over the
-- members' core vertices and edges. For a collision of bodies a and b, b moved by the MTV t:
--  * every point names a member A of a and B of b, lies on A's surface and on the surface of
--    B moved by t (within a tolerance relative to the scene's size), and has a unit normal n
--    (from A toward B) along which the line through the point separates A from B moved:
--    it is the touching face's normal (for two sharp members: perpendicular to an edge of
--    one of them through the point);
--  * its depth is the overlap of A's and B's projections on n before the move, in
--    [0, |t|] (never more than the MTV's depth, exactly);
--  * its pair overlapped before the move and touches after it, and every pair that clearly
--    does (overlap before, and after the move a distance of 0 to round-off) gives a point;
--  * at most 2 points per pair; the contacts' own nx, ny are the MTV's direction.
-- Random convex, rounded, Concave and overlapping compound bodies. STRIKE_SEED=<seed> replays.
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local budget = require('spec.helpers.budget')
local gen = require('spec.property.gen')

local abs, sqrt, cos, sin, pi, max, min = math.abs, math.sqrt, math.cos, math.sin, math.pi, math.max, math.min
local huge = math.huge
local logRange = gen.logRange

local SEED = PRNG.seedFromEnv(20260214)

-- Tolerances, times the scene's scale (its largest coordinate plus radius): a point's
-- distance to a surface, a normal's separation, a depth; a pair "clearly" overlapping before
-- the move, and "clearly" touching after it (for completeness).
local TOL = 1e-7
local CLEAR_OVERLAP, CLEAR_TOUCH = 1e-5, 1e-11

---------------------------------------------------------------------------------------
-- Members, read through public accessors: { xs, ys, n, r, shape } (core vertices in world
-- coordinates; n = 1 for a circle's centre, 2 for a segment).

local function memberOf(s)
  if s.kind == 'circle' then
    local x, y = s:getCentroid()
    return { xs = { x }, ys = { y }, n = 1, r = s:getRadius(), shape = s }
  end
  local v = s:getVertices()
  local n = #v / 2
  local xs, ys = {}, {}
  for i = 1, n do xs[i], ys[i] = v[2 * i - 1], v[2 * i] end
  return { xs = xs, ys = ys, n = n, r = s.getRounding and s:getRounding() or 0, shape = s }
end

local function membersOf(body)
  local list = {}
  if body.elems then
    for s in body:elems() do list[#list + 1] = memberOf(s) end
  else
    list[1] = memberOf(body)
  end
  return list
end

-- A member moved by (tx, ty).
local function moved(M, tx, ty)
  local xs, ys = {}, {}
  for i = 1, M.n do xs[i], ys[i] = M.xs[i] + tx, M.ys[i] + ty end
  return { xs = xs, ys = ys, n = M.n, r = M.r, shape = M.shape }
end

local function pointSegment(px, py, x1, y1, x2, y2)
  local ex, ey = x2 - x1, y2 - y1
  local e2 = ex * ex + ey * ey
  local t = 0
  if e2 > 0 then t = max(0, min(1, ((px - x1) * ex + (py - y1) * ey) / e2)) end
  local dx, dy = px - (x1 + t * ex), py - (y1 + t * ey)
  return sqrt(dx * dx + dy * dy)
end

-- Signed distance from (px, py) to M's core: negative inside a polygon core (n >= 3, convex:
-- inside when the point is on the same side of every edge).
local function coreSigned(M, px, py)
  local n = M.n
  if n == 1 then
    local dx, dy = px - M.xs[1], py - M.ys[1]
    return sqrt(dx * dx + dy * dy)
  end
  local d, pos, neg = huge, 0, 0
  for i = 1, n do
    local j = i % n + 1
    local x1, y1, x2, y2 = M.xs[i], M.ys[i], M.xs[j], M.ys[j]
    d = min(d, pointSegment(px, py, x1, y1, x2, y2))
    local c = (x2 - x1) * (py - y1) - (y2 - y1) * (px - x1)
    if c > 0 then pos = pos + 1 elseif c < 0 then neg = neg + 1 end
  end
  if n >= 3 and (pos == 0 or neg == 0) then return -d end
  return d
end

-- Distance from (px, py) to M's surface (the core grown by its radius).
local function surfaceDistance(M, px, py)
  return abs(coreSigned(M, px, py) - M.r)
end

-- M's projection on (nx, ny): lowest and highest.
local function project(M, nx, ny)
  local lo, hi = huge, -huge
  for i = 1, M.n do
    local p = M.xs[i] * nx + M.ys[i] * ny
    lo, hi = min(lo, p), max(hi, p)
  end
  return lo - M.r, hi + M.r
end

-- The overlap of A's and B's projections on the direction (nx, ny) (any length; none, huge,
-- for a zero vector): the smaller of the two ways, so negative when that direction
-- separates them.
local function axisOverlap(A, B, nx, ny)
  local l = sqrt(nx * nx + ny * ny)
  if l == 0 then return huge end
  nx, ny = nx / l, ny / l
  local alo, ahi = project(A, nx, ny)
  local blo, bhi = project(B, nx, ny)
  return min(ahi - blo, bhi - alo)
end

-- The least overlap over the directions from P's core vertices to Q's core (its centre, or
-- each edge's nearest point), which is the cores' distance when they are apart.
local function vertexAxes(P, Q, A, B)
  local best = huge
  for i = 1, P.n do
    local px, py = P.xs[i], P.ys[i]
    if Q.n == 1 then
      best = min(best, axisOverlap(A, B, Q.xs[1] - px, Q.ys[1] - py))
    else
      for k = 1, Q.n do
        local l = k % Q.n + 1
        local x1, y1, x2, y2 = Q.xs[k], Q.ys[k], Q.xs[l], Q.ys[l]
        local ex, ey = x2 - x1, y2 - y1
        local e2 = ex * ex + ey * ey
        local t = e2 > 0 and max(0, min(1, ((px - x1) * ex + (py - y1) * ey) / e2)) or 0
        best = min(best, axisOverlap(A, B, x1 + t * ex - px, y1 + t * ey - py))
      end
    end
  end
  return best
end

-- How deep A and B overlap (> 0), or minus their distance: over every direction, the least
-- overlap of the projections, brute force over the directions where it can be least: the
-- cores' edge normals (the faces of the Minkowski difference) and the directions between a
-- core vertex of one and the nearest point of the other's core (its arcs, and the distance
-- between cores that are apart).
local function overlap(A, B)
  local best = huge
  for _, M in ipairs({ A, B }) do
    if M.n >= 2 then
      for i = 1, M.n do
        local j = i % M.n + 1
        best = min(best, axisOverlap(A, B, M.ys[j] - M.ys[i], M.xs[i] - M.xs[j]))
      end
    end
  end
  return min(best, vertexAxes(A, B, A, B), vertexAxes(B, A, A, B))
end

local function scaleOf(A, B)
  local s = 1
  for _, list in ipairs({ A, B }) do
    for _, M in ipairs(list) do
      for i = 1, M.n do s = max(s, abs(M.xs[i]) + M.r, abs(M.ys[i]) + M.r) end
    end
  end
  return s
end

---------------------------------------------------------------------------------------
-- Bodies (constructor text kept for failure messages).

local function showArgs(args)
  local parts = {}
  for i = 1, #args do
    local v = args[i]
    if type(v) == 'table' then
      local inner = {}
      for k = 1, #v do inner[k] = ('%.17g'):format(v[k]) end
      if v.radius then inner[#inner + 1] = ('radius = %.17g'):format(v.radius) end
      parts[i] = '{ ' .. table.concat(inner, ', ') .. ' }'
    else
      parts[i] = ('%.17g'):format(v)
    end
  end
  return table.concat(parts, ', ')
end

local function build(group, name, ...)
  return S[group][name](...), ('S.%s.%s(%s)'):format(group, name, showArgs({ ... }))
end

local KINDS = { 'rect', 'rect', 'ngon', 'hull', 'circle', 'capsule', 'roundrect', 'roundhull', 'edge' }

-- The hull of random points in a disk (gift wrapping), as a flat list, or nil when flat.
local function hullPoints(rng, cx, cy, size)
  local xs, ys, k = {}, {}, rng:int(3, 9)
  for i = 1, k do
    local a, r = rng:range(0, 2 * pi), size * sqrt(rng:next())
    xs[i], ys[i] = cx + r * cos(a), cy + r * sin(a)
  end
  local start = 1
  for i = 2, k do if xs[i] < xs[start] or (xs[i] == xs[start] and ys[i] < ys[start]) then start = i end end
  local flat, p = {}, start
  repeat
    flat[#flat + 1], flat[#flat + 2] = xs[p], ys[p]
    local q = p % k + 1
    for i = 1, k do
      local c = (xs[q] - xs[p]) * (ys[i] - ys[p]) - (ys[q] - ys[p]) * (xs[i] - xs[p])
      if c < 0 then q = i end
    end
    p = q
  until p == start or #flat > 2 * k
  if #flat < 6 then return nil end
  local area = 0
  for i = 1, #flat / 2 do
    local j = i % (#flat / 2) + 1
    area = area + flat[2 * i - 1] * flat[2 * j] - flat[2 * j - 1] * flat[2 * i]
  end
  if abs(area) < 0.02 * size * size then return nil end
  return flat
end

local function convexBody(rng, cx, cy, size)
  local kind = KINDS[rng:int(1, #KINDS)]
  local angle = rng:range(-pi, pi)
  if kind == 'rect' then
    -- (axis-aligned one time in three: faces parallel across members, segments of contact)
    if rng:next() < 1 / 3 then angle = 0 end
    return build('hapes', 'Rectangle', cx, cy, size * logRange(rng, 0.2, 2), size * logRange(rng, 0.2, 2), angle)
  elseif kind == 'ngon' then
    return build('hapes', 'RegularPolygon', cx, cy, rng:int(3, 10), size * logRange(rng, 0.3, 1), angle)
  elseif kind == 'circle' then
    return build('hapes', 'Circle', cx, cy, size * logRange(rng, 0.2, 1))
  elseif kind == 'capsule' then
    local w = size * logRange(rng, 0.2, 1)
    return build('hapes', 'Capsule', cx, cy, w, w + size * logRange(rng, 0.1, 2), angle)
  elseif kind == 'roundrect' then
    local w, h = size * logRange(rng, 0.2, 2), size * logRange(rng, 0.2, 2)
    return build('hapes', 'Rectangle', cx, cy, w, h, angle, min(w, h) / 2 * rng:range(0.05, 0.9))
  elseif kind == 'edge' then
    local l = size * logRange(rng, 0.3, 2)
    local dx, dy = l * cos(angle) / 2, l * sin(angle) / 2
    return build('hapes', 'Edge', cx - dx, cy - dy, cx + dx, cy + dy)
  end
  while true do -- 'hull', 'roundhull'
    local flat = hullPoints(rng, cx, cy, size)
    if flat then
      if kind == 'roundhull' then flat.radius = size * logRange(rng, 0.02, 0.4) end
      local ok, shape, text = pcall(build, 'hapes', 'ConvexPolygon', flat)
      if ok then return shape, text end
    end
  end
end

local function concaveBody(rng, cx, cy, R)
  local n = rng:int(4, 14)
  local angles = gen.starAngles(rng, n)
  local flat = {}
  for i = 1, n do
    local r = R * rng:range(0.25, 1)
    flat[2 * i - 1], flat[2 * i] = cx + r * cos(angles[i]), cy + r * sin(angles[i])
  end
  return build('trikers', 'Concave', flat)
end

local function compoundBody(rng, cx, cy, size)
  local texts, xs, ys = {}, { cx }, { cy }
  local c = S.trikers.Collider()
  for i = 1, rng:int(2, 5) do
    local j = rng:int(1, #xs)
    local d, t = size * rng:range(0, 0.7), rng:range(0, 2 * pi)
    local x, y = xs[j] + d * cos(t), ys[j] + d * sin(t)
    xs[#xs + 1], ys[#ys + 1] = x, y
    local s
    s, texts[i] = convexBody(rng, x, y, size * logRange(rng, 0.3, 1))
    c:add(s)
  end
  return c, 'S.trikers.Collider(' .. table.concat(texts, ', ') .. ')'
end

local function nudge(rng, body, text, reach)
  local d, t = reach * rng:range(0, 1), rng:range(0, 2 * pi)
  local dx, dy = d * cos(t), d * sin(t)
  body:translate(dx, dy)
  return body, ('%s:translate(%.17g, %.17g)'):format(text, dx, dy)
end

---------------------------------------------------------------------------------------
-- The check.

local function isSharp(M) return M.r == 0 end

-- Is (px, py) within `tol` of an edge of M to which (nx, ny) is perpendicular (to 1e-9)?
local function perpendicularEdgeThrough(M, px, py, nx, ny, tol)
  if M.n < 2 then return false end
  for i = 1, M.n do
    local j = i % M.n + 1
    local ex, ey = M.xs[j] - M.xs[i], M.ys[j] - M.ys[i]
    local l = sqrt(ex * ex + ey * ey)
    if l > 0 and abs(ex * nx + ey * ny) <= 1e-9 * l
      and pointSegment(px, py, M.xs[i], M.ys[i], M.xs[j], M.ys[j]) <= tol then
      return true
    end
  end
  return false
end

-- Check S.ite of S.triking(a, b); returns a failure message or nil, and whether it collided.
local function check(a, b, stats)
  local m = S.triking(a, b)
  if not m then return nil, false end
  local A, B = membersOf(a), membersOf(b)
  if #A + #B <= 2 then return nil, false end -- (one member each: not a compound MTV)
  local scale = scaleOf(A, B)
  local tol = TOL * scale
  local tx, ty, len = m.x, m.y, m.depth
  local c = S.ite(m)
  if not c then return ('no contacts for a compound MTV (%.17g, %.17g)'):format(tx, ty), true end
  if c.nx ~= m.nx or c.ny ~= m.ny then return 'contacts.nx, ny are not the MTV\'s direction', true end
  if c.count < 1 or #c ~= c.count then return ('count %d, #contacts %d'):format(c.count, #c), true end
  local byPair = {}
  for i = 1, c.count do
    local p = c[i]
    local where = ('point %d (%.17g, %.17g) n (%s, %s) depth %.17g'):format(i, p.x, p.y, tostring(p.nx),
      tostring(p.ny), p.depth)
    local Ai, Bj
    for k, M in ipairs(A) do if M.shape == p.colliderShape then Ai = k end end
    for k, M in ipairs(B) do if M.shape == p.collidedShape then Bj = k end end
    if not (Ai and Bj) then return where .. ': its shapes are not members of the two bodies', true end
    local key = Ai * 1000 + Bj
    byPair[key] = (byPair[key] or 0) + 1
    if byPair[key] > 2 then return where .. ': more than 2 points for one member pair', true end
    for k = 1, i - 1 do -- (one point where a corner meets a corner, not the same one twice)
      local q = c[k]
      if q.colliderShape == p.colliderShape and q.collidedShape == p.collidedShape
        and abs(q.x - p.x) + abs(q.y - p.y) <= 1e-12 * scale then
        return where .. (': the same point as point %d'):format(k), true
      end
    end
    local MA, MB = A[Ai], moved(B[Bj], tx, ty)
    local nx, ny = p.nx, p.ny
    if type(nx) ~= 'number' or abs(nx * nx + ny * ny - 1) > 1e-12 then return where .. ': not a unit normal', true end
    -- on both surfaces, after the move
    local da, db = surfaceDistance(MA, p.x, p.y), surfaceDistance(MB, p.x, p.y)
    if da > tol then return ('%s: %.3g from the first member\'s surface'):format(where, da), true end
    if db > tol then return ('%s: %.3g from the moved second member\'s surface'):format(where, db), true end
    -- the line through it with normal n separates the two after the move
    local _, ahi = project(MA, nx, ny)
    local blo = project(MB, nx, ny)
    local at = nx * p.x + ny * p.y
    if ahi > at + tol or blo < at - tol then
      return ('%s: the first member reaches %.3g past the line along the normal, the second %.3g before it')
        :format(where, ahi - at, at - blo), true
    end
    -- two sharp members: the normal is a face's, through the point
    if isSharp(MA) and isSharp(MB) and not perpendicularEdgeThrough(MA, p.x, p.y, nx, ny, tol)
      and not perpendicularEdgeThrough(MB, p.x, p.y, nx, ny, tol) then
      return where .. ': the normal is not perpendicular to a face of either member through the point', true
    end
    -- depth: the overlap along n before the move, in [0, |t|]
    local lo0 = project(B[Bj], nx, ny)
    local want = ahi - lo0
    if not (p.depth >= 0 and p.depth <= len) then
      return ('%s: depth outside [0, %.17g]'):format(where, len), true
    end
    if abs(p.depth - want) > tol then
      return ('%s: depth, the overlap along the normal before the move is %.17g'):format(where, want), true
    end
    -- the pair pressed into each other along the normal (touching is not colliding), and
    -- touches after the move
    if not (p.depth > 0) then return where .. ': a pair with no depth', true end -- luacheck: ignore 581 (NaN)
    if abs(overlap(MA, MB)) > tol then return where .. ': its pair does not touch after the move', true end
    stats.points = stats.points + 1
    if abs(nx - m.nx) + abs(ny - m.ny) > 1e-6 then stats.turned = stats.turned + 1 end
  end
  -- every pair that clearly overlapped before and clearly touches after gives a point
  for i, MA in ipairs(A) do
    for j, MB0 in ipairs(B) do
      if overlap(MA, MB0) > CLEAR_OVERLAP * scale and abs(overlap(MA, moved(MB0, tx, ty))) <= CLEAR_TOUCH * scale then
        if not byPair[i * 1000 + j] then
          return ('members %d and %d overlap before the move and touch after it, and give no point'):format(i, j), true
        end
        stats.required = stats.required + 1
      end
    end
  end
  return nil, true
end

local function run(name, count, seed, make)
  local rng = PRNG.new(seed)
  local stats = { cases = 0, colliding = 0, points = 0, turned = 0, required = 0 }
  budget.loop(count, function(case)
    local a, ta, b, tb = make(rng, case)
    stats.cases = stats.cases + 1
    local ok, err, hit = pcall(check, a, b, stats)
    if not ok then hit, err = true, 'raised: ' .. tostring(err) end
    if hit then stats.colliding = stats.colliding + 1 end
    if err then
      error(('seed %d (STRIKE_SEED=%d replays), %s case %d: %s; a = %s; b = %s'):format(SEED, SEED, name, case, err,
        ta, tb), 0)
    end
  end)
  return stats
end

-- Where the scenes are: near the origin, or one time in eight far from it.
local function origin(rng)
  local far = rng:next() < 1 / 8 and 1e4 or 50
  return rng:range(-far, far), rng:range(-far, far)
end

-- The scenario must exercise what it claims: enough compound collisions, points whose
-- normal is not the MTV's, and pairs the completeness check demands points of.
local function enough(stats, colliding, seed)
  local share = budget.SHARE -- (of the cases, on this VM)
  assert(stats.colliding > colliding * share and stats.turned > 100 * share and stats.required > 300 * share,
    ('seed %d: %d compound collisions, %d points off the MTV\'s normal, %d pairs that must give points')
      :format(seed, stats.colliding, stats.turned, stats.required))
end

describe('S.ite on compound MTVs (oracle: brute-force surfaces, normals and depths)', function()
  it('compounds of 2-5 overlapping members against convex bodies, either order', function()
    local stats = run('compound vs convex', 1500, SEED, function(rng, case)
      local ox, oy = origin(rng)
      local size = logRange(rng, 0.5, 4)
      local c, tc = compoundBody(rng, ox, oy, size)
      local b, tb = convexBody(rng, ox, oy, size * logRange(rng, 0.3, 1.5))
      b, tb = nudge(rng, b, tb, size)
      if case % 2 == 0 then return c, tc, b, tb end
      return b, tb, c, tc
    end)
    -- (the scenario must exercise pairs whose normal is not the MTV's)
    enough(stats, 600, SEED)
  end)

  it('Concave outlines against convex bodies, either order', function()
    local stats = run('concave vs convex', 1500, SEED + 1, function(rng, case)
      local ox, oy = origin(rng)
      local R = logRange(rng, 1, 6)
      local c, tc = concaveBody(rng, ox, oy, R)
      local b, tb = convexBody(rng, ox, oy, R * logRange(rng, 0.1, 0.6))
      b, tb = nudge(rng, b, tb, R)
      if case % 2 == 0 then return c, tc, b, tb end
      return b, tb, c, tc
    end)
    enough(stats, 600, SEED + 1)
  end)

  it('compounds and Concave outlines against each other', function()
    local stats = run('compound vs compound', 800, SEED + 2, function(rng)
      local ox, oy = origin(rng)
      local size = logRange(rng, 0.5, 4)
      local function side(s)
        if rng:next() < 1 / 3 then return concaveBody(rng, ox, oy, s) end
        return compoundBody(rng, ox, oy, s)
      end
      local a, ta = side(size)
      local b, tb = side(size * logRange(rng, 0.5, 1.5))
      b, tb = nudge(rng, b, tb, size)
      return a, ta, b, tb
    end)
    enough(stats, 300, SEED + 2)
  end)
end)
