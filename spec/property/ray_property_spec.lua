-- Property-based specs for the ray queries (rayIntersections, rayIntersects, rayCast,
-- segmentCast) against the independent oracle in spec/property/ray_brute.lua. Reproduce a
-- failure with STRIKE_SEED=<seed> (any VM); the message names the seed, the case index,
-- the shape at full precision and the ray.
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local brute = require('spec.property.brute')
local rb = require('spec.property.ray_brute')
local gen = require('spec.property.gen')

local abs, max, sqrt, cos, sin, pi, floor = math.abs, math.max, math.sqrt, math.cos, math.sin, math.pi, math.floor

local unpack = table.unpack or unpack -- luacheck: ignore 113 143

local SEED = PRNG.seedFromEnv(20240917)

-- Shape kinds: gen's random convex shapes, unrotated rectangles, and shapes on the integer
-- grid (axis-aligned rectangles, hulls, edges, circles), where axis-aligned rays run along
-- edges and through vertices exactly.
local KINDS = { 'rect', 'ngon', 'hull', 'ellipse', 'circle', 'edge', 'axisRect', 'grid' }

local function makeShape(rng, kind)
  local cx, cy = rng:range(-50, 50), rng:range(-50, 50)
  if kind == 'axisRect' then
    return S.hapes.Rectangle(cx, cy, gen.logRange(rng, 0.1, 8), gen.logRange(rng, 0.1, 8))
  elseif kind == 'grid' then
    return gen.gridShape(S, rng, ({ 'rect', 'hull', 'edge', 'circle' })[rng:int(1, 4)], cx, cy)
  end
  return gen.shape(S, rng, kind, cx, cy)
end

local function g(v) return ('%.17g'):format(v) end

-- A random direction of random length (the length must not matter).
local function direction(rng)
  local a, l = rng:range(-pi, pi), gen.logRange(rng, 0.01, 100)
  return l * cos(a), l * sin(a)
end

-- A ray for the shape (description D) in the given mode: ox, oy, dx, dy and, for the modes
-- that know their answer, the aim point (qx, qy) strictly inside D (on it, for an edge)
-- and for 'vertex' the vertex (vx, vy) the ray passes through first.
local function makeRay(rng, mode, D, shape)
  local cx, cy, R = rb.boundingCircle(D)
  if mode == 'random' then
    local a, d = rng:range(-pi, pi), R * rng:range(0, 3)
    local dx, dy = direction(rng)
    return cx + d * cos(a), cy + d * sin(a), dx, dy
  elseif mode == 'away' then -- outside the bounding circle, pointing away from its centre
    local a, d = rng:range(-pi, pi), R * gen.logRange(rng, 1.05, 4)
    local ox, oy = cx + d * cos(a), cy + d * sin(a)
    local dx, dy
    repeat dx, dy = direction(rng) until dx * (cx - ox) + dy * (cy - oy) < 0
    return ox, oy, dx, dy
  elseif mode == 'interior' then -- from outside the bounding circle toward an inner point
    local qx, qy = rb.interiorPoint(D, rng)
    local a, d = rng:range(-pi, pi), R * gen.logRange(rng, 1.2, 4)
    local ox, oy = cx + d * cos(a), cy + d * sin(a)
    local k = gen.logRange(rng, 0.01, 100)
    return ox, oy, k * (qx - ox), k * (qy - oy), qx, qy
  elseif mode == 'inside' then
    local qx, qy = rb.interiorPoint(D, rng)
    local dx, dy = direction(rng)
    return qx, qy, dx, dy, qx, qy
  elseif mode == 'vertex' then -- through a vertex, then on through an inner point
    local i = rng:int(1, D.n)
    local vx, vy = D.xs[i], D.ys[i]
    local qx, qy = rb.interiorPoint(D, rng)
    local k = gen.logRange(rng, 0.1, 10)
    local ox, oy = vx + k * (vx - qx), vy + k * (vy - qy)
    return ox, oy, qx - ox, qy - oy, qx, qy, vx, vy
  end
  -- 'axis': axis-aligned, from coordinates taken from the vertices (or integers on the
  -- grid), so that rays run along edges and through corners
  local x0, y0, x1, y1 = shape:getBounds()
  local function coord(lo, hi, list)
    local r = rng:int(1, 3)
    if r == 1 and list then return list[rng:int(1, #list)] end
    if r == 2 then return floor(rng:range(lo - 3, hi + 3)) end
    return rng:range(lo - 1, hi + 1)
  end
  local ox, oy = coord(x0, x1, D.xs), coord(y0, y1, D.ys)
  local dir = rng:int(1, 4)
  local dx, dy = ({ 1, -1, 0, 0 })[dir], ({ 0, 0, 1, -1 })[dir]
  local k = ({ 1, 10, 0.25 })[rng:int(1, 3)]
  return ox, oy, k * dx, k * dy
end

describe('ray properties', function()
  it('hits lie on the boundary, sorted, consistent across the four queries and invariant under translation',
    function()
      local rng = PRNG.new(SEED)
      local CASES = 1200
      local counts = {}
      for case = 1, CASES do
        local kind = KINDS[(case - 1) % #KINDS + 1]
        local shape = makeShape(rng, kind)
        local D = brute.of(shape)
        local isCircle, isEdge = D.circle, not D.circle and D.n == 2
        local modes = { 'random', 'away', 'interior', 'inside', 'vertex', 'axis' }
        local mode = modes[rng:int(1, #modes)]
        if isEdge and mode == 'inside' then mode = 'interior' end
        if (isCircle or isEdge) and mode == 'vertex' then mode = 'random' end
        if mode == 'axis' and kind ~= 'axisRect' and kind ~= 'grid' then mode = 'interior' end
        if (kind == 'axisRect' or kind == 'grid') and rng:next() < 0.5 then mode = 'axis' end
        counts[mode] = (counts[mode] or 0) + 1
        local ox, oy, dx, dy, qx, qy, vx, vy = makeRay(rng, mode, D, shape)
        local len = sqrt(dx * dx + dy * dy)
        local ux, uy = dx / len, dy / len
        local scale = max(brute.scale(D, D), abs(ox), abs(oy))
        local tol = 1e-9 * scale

        local function ctx()
          return ('seed %d case %d (%s, %s ray from %s, %s along %s, %s); %s'):format(SEED, case, kind, mode,
            g(ox), g(oy), g(dx), g(dy), gen.show(shape))
        end
        local function check(cond, fmt, ...)
          if not cond then error(ctx() .. ': ' .. fmt:format(...), 2) end
        end

        -- rayIntersections: sorted, >= 0, counted, each hit on the boundary
        local ts, n = shape:rayIntersections(ox, oy, dx, dy)
        check((ts == nil and n == 0) or (type(ts) == 'table' and #ts == n and (n == 1 or n == 2)),
          'malformed result %s, %s', tostring(ts), tostring(n))
        for i = 1, n do
          local t = ts[i]
          check(t >= 0 and t < math.huge, 'hit %d at t = %s', i, g(t))
          if i > 1 then check(t > ts[i - 1], 'hits not ascending: %s then %s', g(ts[i - 1]), g(t)) end
          local d = rb.boundaryDist(D, ox + t * ux, oy + t * uy)
          check(d <= tol, 'hit %d at t = %s is %s from the boundary', i, g(t), g(d))
        end
        -- a reused table gives the same values
        local reuse = { 1, 2, 3 }
        local ts2, n2 = shape:rayIntersections(ox, oy, dx, dy, reuse)
        check(n2 == n and (ts2 == nil or (ts2 == reuse and #reuse == n)), 'ts reuse gave %s values', tostring(n2))
        for i = 1, n do check(reuse[i] == ts[i], 'ts reuse: value %d differs', i) end
        -- rayIntersects
        check(shape:rayIntersects(ox, oy, dx, dy) == (ts ~= nil), 'rayIntersects disagrees with rayIntersections')

        -- rayCast: the least hit, its point, an outward unit normal supporting the shape there
        local t, hx, hy, nx, ny = shape:rayCast(ox, oy, dx, dy)
        check((t == nil) == (ts == nil), 'rayCast %s but rayIntersections %s', tostring(t), tostring(ts))
        if t then
          check(t == ts[1], 'rayCast distance %s, least hit %s', g(t), g(ts[1]))
          check(abs(hx - (ox + t * ux)) <= tol and abs(hy - (oy + t * uy)) <= tol, 'rayCast point (%s, %s)',
            g(hx), g(hy))
          check(abs(nx * nx + ny * ny - 1) <= 1e-12, 'normal (%s, %s) not unit', g(nx), g(ny))
          if isCircle then
            check(abs(nx - (hx - D.x) / D.r) <= 1e-9 and abs(ny - (hy - D.y) / D.r) <= 1e-9,
              'circle normal (%s, %s)', g(nx), g(ny))
          else
            for i = 1, D.n do -- every vertex on the inner side of the line through the hit
              local s = nx * (D.xs[i] - hx) + ny * (D.ys[i] - hy)
              check(s <= tol, 'normal (%s, %s) does not support the shape: vertex %d is %s in front',
                g(nx), g(ny), i, g(s))
            end
          end
          if rb.inside(D, ox, oy) then
            check(nx * ux + ny * uy >= -1e-9, 'starting inside, the exit normal faces back')
          elseif rb.inside(D, ox + (t + tol) * ux, oy + (t + tol) * uy) then
            -- (not for a graze or a ray along an edge: nothing to say about those)
            check(nx * ux + ny * uy <= 1e-9, 'entering, the normal faces along the ray')
          end
          -- maxDistance: the same hit up to it, nil past it
          local m = rng:range(0, 2) * t
          local t2 = shape:rayCast(ox, oy, dx, dy, m)
          check((t2 == t) == (t <= m) and (t2 == nil) == (t > m), 'maxDistance %s gave %s (hit at %s)', g(m),
            tostring(t2), g(t))
          -- segmentCast along the same ray: the hit when the segment reaches well past it
          local L = t * rng:range(0.5, 2) + rng:range(0, 1)
          local st = shape:segmentCast(ox, oy, ox + L * ux, oy + L * uy)
          if L > t + tol then
            check(st and abs(st - t) <= tol, 'segmentCast of length %s gave %s (rayCast %s)', g(L), tostring(st), g(t))
          elseif L < t - tol then
            check(st == nil, 'segmentCast of length %s gave %s (rayCast %s)', g(L), tostring(st), g(t))
          end
        end

        -- mode expectations
        if mode == 'away' then
          check(ts == nil, 'pointing away from outside the bounding circle, yet %d hits', n)
        elseif mode == 'interior' or mode == 'vertex' then
          local dq = sqrt((qx - ox) ^ 2 + (qy - oy) ^ 2)
          local lo, hi = rb.hitRange(D, ox, oy, ux, uy)
          if isEdge then
            check(n == 1, 'aimed at an inner point of an edge: %d hits', n)
            check(abs(ts[1] - dq) <= tol, 'edge hit at %s, aim point at %s', g(ts[1]), g(dq))
          else
            check(n == 2, 'aimed at an inner point from outside: %d hits', n)
            check(ts[1] < dq and dq < ts[2], 'aim point at %s not between the hits %s, %s', g(dq), g(ts[1]), g(ts[2]))
            check(lo and abs(ts[1] - lo) <= tol and abs(ts[2] - hi) <= tol, 'hits %s, %s; oracle %s, %s', g(ts[1]),
              g(ts[2]), tostring(lo), tostring(hi))
          end
          if mode == 'vertex' then
            local dv = sqrt((vx - ox) ^ 2 + (vy - oy) ^ 2)
            check(abs(ts[1] - dv) <= tol, 'through vertex (%s, %s) at %s, first hit %s', g(vx), g(vy), g(dv), g(ts[1]))
          end
        elseif mode == 'inside' then
          check(n == 1, 'from inside: %d hits', n)
          local _, hi = rb.hitRange(D, ox, oy, ux, uy)
          check(hi and abs(ts[1] - hi) <= tol, 'exit at %s, oracle %s', g(ts[1]), tostring(hi))
        end

        -- translating ray and shape together changes nothing. Not compared for the 'axis'
        -- rays, built to run exactly along edges and through corners: a shape's world
        -- vertices are its centroid plus local offsets, so a translation may move a
        -- corner by a rounding, and a ray along an edge may then miss it or run just inside.
        if mode ~= 'axis' then
          local tx, ty = rng:range(-100, 100), rng:range(-100, 100)
          local moved = shape:copy():translate(tx, ty)
          local mts, mn = moved:rayIntersections(ox + tx, oy + ty, dx, dy)
          local ttol = 1e-9 * (scale + abs(tx) + abs(ty))
          check(mn == n, 'translated by (%s, %s): %d hits instead of %d', g(tx), g(ty), mn, n)
          for i = 1, n do
            check(abs(mts[i] - ts[i]) <= ttol, 'translated by (%s, %s): hit %d at %s instead of %s', g(tx), g(ty), i,
              g(mts[i]), g(ts[i]))
          end
        end
      end
      -- guard against a vacuous property: every mode ran
      for _, mode in ipairs({ 'random', 'away', 'interior', 'inside', 'vertex', 'axis' }) do
        assert((counts[mode] or 0) >= 40, ('seed %d: only %d cases of mode %s'):format(SEED, counts[mode] or 0, mode))
      end
    end)

  it('a collider reports what its leaves report: the first hit (first leaf on ties) and every list', function()
    local rng = PRNG.new(SEED + 1)
    for case = 1, 200 do
      local cx, cy = rng:range(-50, 50), rng:range(-50, 50)
      local leaves = {}
      for i = 1, rng:int(1, 4) do
        local kind = KINDS[rng:int(1, #KINDS)]
        if kind == 'grid' then
          leaves[i] = gen.gridShape(S, rng, ({ 'rect', 'hull', 'edge', 'circle' })[rng:int(1, 4)], cx, cy)
        elseif kind == 'axisRect' then
          leaves[i] = S.hapes.Rectangle(cx + rng:range(-4, 4), cy + rng:range(-4, 4), rng:range(1, 4))
        else
          leaves[i] = gen.shape(S, rng, kind, cx + rng:range(-4, 4), cy + rng:range(-4, 4))
        end
      end
      if rng:next() < 0.2 then leaves[#leaves + 1] = leaves[1]:copy() end -- an exact tie
      local c
      if #leaves >= 3 then
        c = S.trikers.Collider(leaves[1], S.trikers.Collider(leaves[2], leaves[3]), select(4, unpack(leaves)))
      else
        c = S.trikers.Collider(unpack(leaves))
      end
      local order = {}
      for s in c:elems() do order[#order + 1] = s end
      local a, d = rng:range(-pi, pi), rng:range(0, 15)
      local ox, oy = cx + d * cos(a), cy + d * sin(a)
      local dx, dy = direction(rng)
      if rng:next() < 0.5 then -- aim at the middle of the group
        dx, dy = cx + rng:range(-2, 2) - ox, cy + rng:range(-2, 2) - oy
      end
      local function ctx()
        local shown = {}
        for i, s in ipairs(order) do shown[i] = gen.show(s) end
        return ('seed %d case %d (ray from %s, %s along %s, %s; leaves %s)'):format(SEED + 1, case, g(ox), g(oy),
          g(dx), g(dy), table.concat(shown, '; '))
      end

      local bt, bs, bx, by, bnx, bny, any = nil, nil, nil, nil, nil, nil, false
      local map = c:rayIntersections(ox, oy, dx, dy)
      for _, s in ipairs(order) do
        local ts = s:rayIntersections(ox, oy, dx, dy)
        any = any or ts ~= nil
        local got = map and map[s]
        assert((got == nil) == (ts == nil), ctx() .. ': rayIntersections map entry disagrees with the leaf')
        if ts then
          assert(#got == #ts, ctx() .. ': list lengths differ')
          for i = 1, #ts do assert(got[i] == ts[i], ctx() .. ': list values differ') end
        end
        local t, x, y, nx, ny = s:rayCast(ox, oy, dx, dy)
        if t and (bt == nil or t < bt) then bt, bs, bx, by, bnx, bny = t, s, x, y, nx, ny end
      end
      assert((map == nil) == not any, ctx() .. ': rayIntersections should be nil exactly when nothing is hit')
      assert(c:rayIntersects(ox, oy, dx, dy) == any, ctx() .. ': rayIntersects disagrees with the leaves')
      local t, x, y, nx, ny, s = c:rayCast(ox, oy, dx, dy)
      assert(t == bt and s == bs and x == bx and y == by and nx == bnx and ny == bny,
        ('%s: collider rayCast %s on %s, leaves give %s on %s'):format(ctx(), tostring(t), tostring(s), tostring(bt),
          tostring(bs)))
      if bt then
        local L = bt * 2 + 1
        local len = sqrt(dx * dx + dy * dy)
        local st, _, _, _, _, ss = c:segmentCast(ox, oy, ox + L * dx / len, oy + L * dy / len)
        assert(st and abs(st - bt) <= 1e-9 * max(1, abs(ox), abs(oy), L) and ss,
          ('%s: segmentCast %s, rayCast %s'):format(ctx(), tostring(st), tostring(bt)))
      end
    end
  end)
end)
