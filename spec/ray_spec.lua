-- Ray queries: rayIntersections, rayIntersects, rayCast and segmentCast on shapes and
-- colliders. Exact cases; random ones are in spec/property/ray_property_spec.lua.
local S = require('strike')
local expect = require('spec.helpers.expect')

local H, T = S.hapes, S.trikers
local near = expect.near
local sqrt = math.sqrt

-- rayIntersections as a plain list (nil on a miss), checking that n matches it.
local function hits(shape, x, y, dx, dy)
  local ts, n = shape:rayIntersections(x, y, dx, dy)
  if ts == nil then
    assert.equals(0, n)
    assert.is_false(shape:rayIntersects(x, y, dx, dy))
    return nil
  end
  assert.equals(#ts, n)
  assert.is_true(shape:rayIntersects(x, y, dx, dy))
  return ts
end

-- rayCast's five values as a list (nil on a miss).
local function cast(shape, ...)
  local t, x, y, nx, ny = shape:rayCast(...)
  if t == nil then return nil end
  return { t, x, y, nx, ny }
end

local function segcast(shape, ...)
  local t, x, y, nx, ny = shape:segmentCast(...)
  if t == nil then return nil end
  return { t, x, y, nx, ny }
end

local TOL = 1e-12

describe('rays on polygons', function()
  local box = H.Rectangle(0, 0, 4, 2) -- x in [-2, 2], y in [-1, 1]

  it('pass through an axis-aligned rectangle horizontally and vertically (two hits)', function()
    -- (the original Strike stopped at the first edge parallel to the ray)
    expect.nearList(hits(box, -5, 0, 1, 0), { 3, 7 }, TOL)
    expect.nearList(hits(box, 5, 0.5, -1, 0), { 3, 7 }, TOL)
    expect.nearList(hits(box, 0.5, -4, 0, 1), { 3, 5 }, TOL)
    expect.nearList(hits(box, -1.5, 4, 0, -1), { 3, 5 }, TOL)
    local far = H.Rectangle(1000, -500, 10, 6)
    expect.nearList(hits(far, 900, -500, 1, 0), { 95, 105 }, TOL)
    expect.nearList(hits(far, 1001, -400, 0, -1), { 97, 103 }, TOL)
  end)

  it('count a graze through a corner once, with the entering face as the normal', function()
    local sq = H.Rectangle(0, 0, 2, 2)
    local ts, n = sq:rayIntersections(-2, 0, 1, 1)
    assert.equals(1, n)
    assert.equals(1, #ts)
    near(ts[1], sqrt(2), TOL)
    expect.nearList(cast(sq, -2, 0, 1, 1), { sqrt(2), -1, 1, -1, 0 }, TOL)
    -- through the corner and on through the inside: two hits; on ties between two entering
    -- faces the first face in order (edge 1, the min-y side) gives the normal
    expect.nearList(hits(sq, -3, -3, 1, 1), { 2 * sqrt(2), 4 * sqrt(2) }, TOL)
    expect.nearList(cast(sq, -3, -3, 1, 1), { 2 * sqrt(2), -1, -1, 0, -1 }, TOL)
  end)

  it('running exactly along an edge report the ends of that edge', function()
    local sq = H.Rectangle(0, 0, 2, 2)
    expect.nearList(hits(sq, -3, -1, 1, 0), { 2, 4 }, TOL)
    expect.nearList(hits(sq, 1, 5, 0, -1), { 4, 6 }, TOL)
    expect.nearList(hits(sq, 4, 1, -2, 0), { 3, 5 }, TOL)
    expect.nearList(cast(sq, -3, -1, 1, 0), { 2, -1, -1, -1, 0 }, TOL)
    assert.is_nil(hits(sq, -3, -1.000001, 1, 0))
  end)

  it('starting inside report only the exit', function()
    local ts, n = box:rayIntersections(0, 0, 1, 0)
    assert.equals(1, n)
    expect.nearList(ts, { 2 }, TOL)
    expect.nearList(hits(box, 0, 0.5, 0, -3), { 1.5 }, TOL)
    expect.nearList(cast(box, 0, 0, 1, 0), { 2, 2, 0, 1, 0 }, TOL) -- normal along the ray
    expect.nearList(cast(box, 1, 0, 0, -1), { 1, 1, -1, 0, -1 }, TOL)
  end)

  it('pointing away, or passing by, miss', function()
    assert.is_nil(hits(box, -5, 0, -1, 0))
    assert.is_nil(hits(box, -5, 3, 1, 0))
    assert.is_nil(hits(box, 0, 5, 1, 1))
    assert.is_nil(cast(box, -5, 0, -1, 0))
    local ts, n = box:rayIntersections(-5, 0, -1, 0)
    assert.is_nil(ts)
    assert.equals(0, n)
  end)

  it('starting on the boundary report 0 first when entering, and just 0 when leaving', function()
    expect.nearList(hits(box, -2, 0, 1, 0), { 0, 4 }, TOL)
    expect.nearList(hits(box, 2, 0, 1, 0), { 0 }, TOL)
    expect.nearList(hits(box, 0, 1, 0, -1), { 0, 2 }, TOL)
    expect.nearList(cast(box, -2, 0, 1, 0), { 0, -2, 0, -1, 0 }, TOL)
    expect.nearList(cast(box, 2, 0, 1, 0), { 0, 2, 0, 1, 0 }, TOL)
    local t = box:rayCast(-2, 0, 1, 0)
    assert.equals('0', ('%g'):format(t)) -- never a negative zero
  end)

  it('measure distances along the normalised direction (its length does not matter)', function()
    local ts1 = hits(box, -5, 0, 1, 0)
    local ts10 = hits(box, -5, 0, 10, 0)
    assert.same(ts1, ts10)
    local a, b = hits(box, -3, -2, 0.6, 0.8), hits(box, -3, -2, 60, 80)
    expect.nearList(a, b, TOL)
    expect.nearList(hits(box, -5, 0, 1e-200, 0), { 3, 7 }, TOL) -- no underflow
    expect.nearList(hits(box, -5, -3, 1e300, 1e300), hits(box, -5, -3, 1, 1), TOL) -- no overflow
    near(box:rayCast(-5, 0, 10, 0), 3, TOL)
  end)

  it('follow the shape as it moves, turns and scales', function()
    local r = H.Rectangle(0, 0, 2, 2)
    r:translate(10, 0)
    expect.nearList(hits(r, 0, 0, 1, 0), { 9, 11 }, TOL)
    r:rotate(math.pi / 4)
    expect.nearList(hits(r, 0, 0, 1, 0), { 10 - sqrt(2), 10 + sqrt(2) }, TOL)
    r:scale(2)
    expect.nearList(hits(r, 0, 0, 1, 0), { 10 - 2 * sqrt(2), 10 + 2 * sqrt(2) }, TOL)
  end)

  it('work on every polygon class', function()
    local hex = H.RegularPolygon(0, 0, 6, 2) -- vertex 6 at (0, 2): flat sides at x = +-sqrt(3)
    expect.nearList(hits(hex, -5, 0, 1, 0), { 5 - sqrt(3), 5 + sqrt(3) }, TOL)
    local ell = H.Ellipse(0, 0, 4, 2, 4) -- a diamond through (+-4, 0), (0, +-2)
    expect.nearList(hits(ell, -6, 0, 1, 0), { 2, 10 }, TOL)
    local tri = H.ConvexPolygon(0, 0, 4, 0, 0, 4)
    expect.nearList(hits(tri, 1, -1, 0, 1), { 1, 4 }, TOL)
    expect.nearList(cast(tri, 1, 10, 0, -1), { 7, 1, 3, sqrt(0.5), sqrt(0.5) }, TOL)
  end)
end)

describe('rays on circles', function()
  local c = H.Circle(0, 0, 2)

  it('through the centre: two hits, the normal facing the ray', function()
    expect.nearList(hits(c, -5, 0, 1, 0), { 3, 7 }, TOL)
    expect.nearList(hits(c, 0, 5, 0, -2), { 3, 7 }, TOL)
    expect.nearList(cast(c, -5, 0, 1, 0), { 3, -2, 0, -1, 0 }, TOL)
    local d = 5 / sqrt(2)
    expect.nearList(hits(c, -d, -d, 1, 1), { 3, 7 }, TOL)
  end)

  it('tangent: one hit', function()
    local ts, n = c:rayIntersections(-5, 2, 1, 0)
    assert.equals(1, n)
    expect.nearList(ts, { 5 }, 0)
    expect.nearList(cast(c, -5, 2, 1, 0), { 5, 0, 2, 0, 1 }, TOL)
    assert.is_nil(hits(c, -5, 2.000001, 1, 0))
  end)

  it('from inside: the exit only, normal along the ray', function()
    expect.nearList(hits(c, 0, 0, 0, 1), { 2 }, TOL)
    expect.nearList(hits(c, 1, 0, -1, 0), { 3 }, TOL)
    expect.nearList(cast(c, 0, 0, 0, 1), { 2, 0, 2, 0, 1 }, TOL)
  end)

  it('from the circle itself: 0 first when entering, just 0 when leaving', function()
    expect.nearList(hits(c, -2, 0, 1, 0), { 0, 4 }, TOL)
    expect.nearList(hits(c, 2, 0, 1, 0), { 0 }, TOL)
    expect.nearList(hits(c, 0, 2, 1, 0), { 0 }, TOL) -- tangent at the origin
    assert.equals('0', ('%g'):format((c:rayCast(2, 0, 1, 0))))
  end)

  it('miss when pointing away or passing by, and follow scale', function()
    assert.is_nil(hits(c, -5, 0, -1, 0))
    assert.is_nil(hits(c, -5, 3, 1, 0))
    local big = H.Circle(10, 10, 1):scale(3)
    expect.nearList(hits(big, 10, 0, 0, 1), { 7, 13 }, TOL)
  end)
end)

describe('rays on edges', function()
  local e = H.Edge(0, -1, 0, 1)

  it('crossing: one hit, the normal on the side of the origin', function()
    expect.nearList(hits(e, -3, 0.5, 1, 0), { 3 }, TOL)
    expect.nearList(cast(e, -3, 0.5, 1, 0), { 3, 0, 0.5, -1, 0 }, TOL)
    expect.nearList(cast(e, 3, 0.5, -1, 0), { 3, 0, 0.5, 1, 0 }, TOL)
    expect.nearList(hits(e, -3, 1, 1, 0), { 3 }, TOL) -- exactly through an end
    expect.nearList(hits(e, -1, -2, 1, 1), { sqrt(2) }, TOL)
    assert.is_nil(hits(e, -3, 1.5, 1, 0))
    assert.is_nil(hits(e, 3, 0, 1, 0))
  end)

  it('collinear: the ends of the overlap', function()
    expect.nearList(hits(e, 0, -3, 0, 1), { 2, 4 }, TOL)
    expect.nearList(hits(e, 0, 5, 0, -1), { 4, 6 }, TOL)
    expect.nearList(hits(e, 0, 0, 0, 1), { 1 }, TOL) -- from on the segment: its far end
    expect.nearList(cast(e, 0, -3, 0, 1), { 2, 0, -1, 0, -1 }, TOL)
    expect.nearList(cast(e, 0, 0, 0, 1), { 1, 0, 1, 0, 1 }, TOL)
    assert.is_nil(hits(e, 0, -3, 0, -1))
    local diag = H.Edge(1, 1, 3, 3)
    expect.nearList(hits(diag, 0, 0, 1, 1), { sqrt(2), 3 * sqrt(2) }, TOL)
  end)

  it('parallel on another line: no hit', function()
    assert.is_nil(hits(e, 1, -3, 0, 1))
    assert.is_nil(hits(e, -1e-9, -3, 0, 1))
    assert.is_nil(cast(e, 1, -3, 0, 1))
  end)
end)

describe('rayCast and segmentCast', function()
  local sq = H.Rectangle(0, 0, 2, 2)

  it('rayCast stops at maxDistance (inclusive)', function()
    assert.is_nil(cast(sq, -3, 0, 1, 0, 1.9))
    expect.nearList(cast(sq, -3, 0, 1, 0, 2), { 2, -1, 0, -1, 0 }, TOL)
    expect.nearList(cast(sq, -3, 0, 1, 0, math.huge), { 2, -1, 0, -1, 0 }, TOL)
    expect.nearList(cast(sq, -1, 0, 1, 0, 0), { 0, -1, 0, -1, 0 }, TOL)
    assert.is_nil(cast(sq, 0, 0, 1, 0, 0.5)) -- the exit is at 1
    assert.is_nil(cast(H.Circle(0, 0, 1), -3, 0, 1, 0, 1))
    assert.is_nil(cast(H.Edge(0, -1, 0, 1), -3, 0, 1, 0, 2.5))
  end)

  it('segmentCast reports distances in units of length, up to p2 inclusive', function()
    expect.nearList(segcast(sq, -3, 0, 3, 0), { 2, -1, 0, -1, 0 }, TOL)
    expect.nearList(segcast(sq, -30, 0, 30, 0), { 29, -1, 0, -1, 0 }, TOL)
    expect.nearList(segcast(sq, -3, 0, -1, 0), { 2, -1, 0, -1, 0 }, TOL)
    assert.is_nil(segcast(sq, -3, 0, -1.5, 0))
    expect.nearList(segcast(sq, 0, 0, 0, 5), { 1, 0, 1, 0, 1 }, TOL) -- from inside: the exit
    assert.is_nil(segcast(sq, 0, 0, 0.5, 0)) -- wholly inside: no boundary point
    assert.is_nil(segcast(sq, 5, 5, 5, 5)) -- p1 == p2: no hit, no error
    assert.is_nil(segcast(sq, 0, 0, 0, 0))
    expect.nearList(segcast(H.Circle(0, 0, 1), 0, 5, 0, -5), { 4, 0, 1, 0, 1 }, TOL)
    expect.nearList(segcast(H.Edge(0, -1, 0, 1), 4, 0, -4, 0), { 4, 0, 0, 1, 0 }, TOL)
    -- coordinates whose difference overflows
    local t = sq:segmentCast(-1.5e308, 0, 1.5e308, 0)
    near(t, 1.5e308 - 1, 1e293)
  end)

  it('the distance is the first value of rayIntersections', function()
    for _, shape in ipairs({ sq, H.Circle(0, 0, 1), H.Edge(-1, -1, 1, 1), H.RegularPolygon(0, 0, 7, 1) }) do
      for _, ray in ipairs({ { -3, 0.2, 1, 0 }, { 0.1, 0.1, 0, 1 }, { 2, 3, -1, -1.3 } }) do
        local ts = shape:rayIntersections(ray[1], ray[2], ray[3], ray[4])
        local t = shape:rayCast(ray[1], ray[2], ray[3], ray[4])
        if ts then assert.equals(ts[1], t) else assert.is_nil(t) end
      end
    end
  end)

  it('never hangs or errors on huge finite coordinates', function()
    for _, shape in ipairs({ sq, H.Circle(0, 0, 1), H.Edge(-1, -1, 1, 1) }) do
      for _, ray in ipairs({ { 1e308, 1e308, -1, -1 }, { -1.7e308, 0, 1e308, 1e-308 }, { 0, 0, 1e308, 1e308 } }) do
        local ts, n = shape:rayIntersections(ray[1], ray[2], ray[3], ray[4])
        for i = 1, n do assert.is_true(ts[i] >= 0 and ts[i] < math.huge) end
        local t = shape:rayCast(ray[1], ray[2], ray[3], ray[4])
        assert.is_true(t == nil or t >= 0)
      end
    end
  end)
end)

describe('reused ts tables', function()
  it('are filled from index 1, returned, and cleared past the count', function()
    local sq = H.Rectangle(0, 0, 2, 2)
    local ts = { 9, 9, 9, 9, 9 }
    local got, n = sq:rayIntersections(-3, 0, 1, 0, ts)
    assert.equals(ts, got)
    assert.equals(2, n)
    assert.same({ 2, 4 }, ts)
    got, n = sq:rayIntersections(0, 0, 1, 0, ts)
    assert.equals(ts, got)
    assert.equals(1, n)
    assert.same({ 1 }, ts)
    got, n = sq:rayIntersections(-3, 5, 1, 0, ts)
    assert.is_nil(got)
    assert.equals(0, n)
    assert.same({}, ts)
    ts[1], ts[2], ts[3] = 7, 7, 7
    got, n = H.Circle(0, 0, 1):rayIntersections(-3, 1, 1, 0, ts)
    assert.equals(ts, got)
    assert.equals(1, n)
    assert.same({ 3 }, ts)
  end)

  it('are never kept by strike: each call without ts returns a new table', function()
    local sq = H.Rectangle(0, 0, 2, 2)
    local a = sq:rayIntersections(-3, 0, 1, 0)
    local b = sq:rayIntersections(-3, 0, 1, 0)
    assert.are_not.equal(a, b)
    assert.same(a, b)
  end)
end)

describe('rays on colliders', function()
  local rect, circle, edge = H.Rectangle(0, 0, 2, 2), H.Circle(5, 0, 1), H.Edge(10, -1, 10, 1)
  local c = T.Collider(rect, T.Collider(circle), edge, H.Circle(0, 10, 1))

  it('rayIntersections maps each leaf hit to its list', function()
    local r = c:rayIntersections(-3, 0, 1, 0)
    local count = 0
    for _ in pairs(r) do count = count + 1 end
    assert.equals(3, count)
    assert.same({ 2, 4 }, r[rect])
    expect.nearList(r[circle], { 7, 9 }, TOL)
    expect.nearList(r[edge], { 13 }, TOL)
    assert.is_nil(c:rayIntersections(-3, 50, 1, 0))
    assert.is_nil(T.Collider():rayIntersections(0, 0, 1, 0))
  end)

  it('rayIntersects is true when any leaf is hit', function()
    assert.is_true(c:rayIntersects(-3, 0, 1, 0))
    assert.is_true(c:rayIntersects(0, 20, 0, -1))
    assert.is_false(c:rayIntersects(-3, 50, 1, 0))
    assert.is_false(T.Collider():rayIntersects(0, 0, 1, 0))
  end)

  it('rayCast and segmentCast return the first hit and its leaf', function()
    local t, x, y, nx, ny, s = c:rayCast(-3, 0, 1, 0)
    expect.nearList({ t, x, y, nx, ny }, { 2, -1, 0, -1, 0 }, TOL)
    assert.equals(rect, s)
    t, x, y, nx, ny, s = c:rayCast(20, 0, -1, 0)
    expect.nearList({ t, x, y, nx, ny }, { 10, 10, 0, 1, 0 }, TOL)
    assert.equals(edge, s)
    t, x, y, nx, ny, s = c:rayCast(7, 0, -1, 0)
    expect.nearList({ t, x, y, nx, ny }, { 1, 6, 0, 1, 0 }, TOL)
    assert.equals(circle, s)
    assert.is_nil(c:rayCast(-3, 0, 1, 0, 1.5))
    assert.is_nil(c:rayCast(-3, 50, 1, 0))
    assert.is_nil(T.Collider():rayCast(0, 0, 1, 0))
    t, x, y, nx, ny, s = c:segmentCast(8, 0, 2, 0)
    expect.nearList({ t, x, y, nx, ny }, { 2, 6, 0, 1, 0 }, TOL)
    assert.equals(circle, s)
    assert.is_nil(c:segmentCast(7, 0, 6.5, 0))
    assert.is_nil(c:segmentCast(7, 0, 7, 0))
  end)

  it('on ties, rayCast returns the leaf that comes first in elems() order', function()
    local a, b = H.Rectangle(0, 0, 2, 2), H.Rectangle(0, 0, 2, 2)
    local twins = T.Collider(T.Collider(a), b)
    local _, _, _, _, _, s = twins:rayCast(-3, 0, 1, 0)
    assert.equals(twins:elems()(twins), s)
    assert.equals(a, s)
    _, _, _, _, _, s = T.Collider(b:copy(), a:copy()):rayCast(-3, 0, 1, 0)
    assert.is_true(s:getCentroid() == 0)
  end)

  it('work on Capsules and single-shape colliders', function()
    local cap = T.Capsule(0, 0, 2, 6) -- caps of radius 1 centred at y = +-2
    local t, _, _, nx, ny = cap:rayCast(0, -10, 0, 1)
    near(t, 7, TOL)
    expect.nearList({ nx, ny }, { 0, -1 }, TOL)
    t = cap:rayCast(-10, 0, 1, 0)
    near(t, 9, TOL)
    local one = T.Circle(0, 0, 1)
    expect.nearList(one:rayIntersections(-3, 0, 1, 0)[(one:unpack())], { 2, 4 }, TOL)
  end)
end)

describe('ray argument errors', function()
  local sq, circle, edge = H.Rectangle(0, 0, 2, 2), H.Circle(0, 0, 1), H.Edge(0, 0, 1, 1)
  local c = T.Collider(H.Rectangle(0, 0, 2, 2))
  local nan, inf = 0 / 0, math.huge

  it('name the function and the argument, at the caller\'s line', function()
    expect.raisesAt(function() sq:rayIntersections(nil, 0, 1, 0) end,
      'strike.Shape:rayIntersections: x must be a finite number, got nil')
    expect.raisesAt(function() sq:rayIntersections(0, 'a', 1, 0) end,
      'strike.Shape:rayIntersections: y must be a finite number, got string "a"')
    expect.raisesAt(function() sq:rayIntersections(0, 0, nan, 0) end,
      'strike.Shape:rayIntersections: dx must be a finite number, got nan')
    expect.raisesAt(function() sq:rayIntersections(0, 0, 1, inf) end,
      'strike.Shape:rayIntersections: dy must be a finite number, got inf')
    expect.raisesAt(function() sq:rayIntersections(0, 0, 0, 0) end,
      'strike.Shape:rayIntersections: the direction must not be zero')
    expect.raisesAt(function() sq:rayIntersections(0, 0, 1, 0, 5) end,
      'strike.Shape:rayIntersections: ts must be a table or nil, got 5')
    expect.raisesAt(function() sq:rayIntersections(0, 0, 1, 0, 'x') end, 'ts must be a table or nil, got string "x"')
    expect.raisesAt(function() circle:rayIntersections(-inf, 0, 1, 0) end,
      'strike.Shape:rayIntersections: x must be a finite number, got -inf')
    expect.raisesAt(function() edge:rayIntersections(0, 0, 0, -0) end,
      'strike.Shape:rayIntersections: the direction must not be zero')
    expect.raisesAt(function() circle:rayIntersections(0, 0, 1, 0, true) end, 'ts must be a table or nil, got true')

    expect.raisesAt(function() sq:rayIntersects(0, 0, nil, 1) end,
      'strike.Shape:rayIntersects: dx must be a finite number, got nil')
    expect.raisesAt(function() circle:rayIntersects(0, nan, 1, 1) end,
      'strike.Shape:rayIntersects: y must be a finite number, got nan')
    expect.raisesAt(function() edge:rayIntersects(0, 0, 0, 0) end,
      'strike.Shape:rayIntersects: the direction must not be zero')

    expect.raisesAt(function() sq:rayCast(0, 0, nil, 0) end,
      'strike.Shape:rayCast: dx must be a finite number, got nil')
    expect.raisesAt(function() sq:rayCast(0, 0, 0, 0) end, 'strike.Shape:rayCast: the direction must not be zero')
    expect.raisesAt(function() sq:rayCast(0, 0, 1, 0, -1) end,
      'strike.Shape:rayCast: maxDistance must be a number >= 0 or nil, got -1')
    expect.raisesAt(function() sq:rayCast(0, 0, 1, 0, nan) end,
      'strike.Shape:rayCast: maxDistance must be a number >= 0 or nil, got nan')
    expect.raisesAt(function() circle:rayCast(0, 0, 1, 0, '5') end,
      'strike.Shape:rayCast: maxDistance must be a number >= 0 or nil, got string "5"')
    expect.raisesAt(function() edge:rayCast(0, 0, 1, 0, -inf) end,
      'strike.Shape:rayCast: maxDistance must be a number >= 0 or nil, got -inf')
    expect.raisesAt(function() circle:rayCast(inf, 0, 1, 0) end,
      'strike.Shape:rayCast: x must be a finite number, got inf')
    expect.raisesAt(function() edge:rayCast(0, 0, 0, {}) end,
      'strike.Shape:rayCast: dy must be a finite number, got table')

    expect.raisesAt(function() sq:segmentCast(nil, 0, 1, 1) end,
      'strike.Shape:segmentCast: x1 must be a finite number, got nil')
    expect.raisesAt(function() sq:segmentCast(0, nan, 1, 1) end,
      'strike.Shape:segmentCast: y1 must be a finite number, got nan')
    expect.raisesAt(function() circle:segmentCast(0, 0, inf, 1) end,
      'strike.Shape:segmentCast: x2 must be a finite number, got inf')
    expect.raisesAt(function() edge:segmentCast(0, 0, 1, '1') end,
      'strike.Shape:segmentCast: y2 must be a finite number, got string "1"')
  end)

  it('on colliders too', function()
    expect.raisesAt(function() c:rayIntersections(nil, 0, 1, 0) end,
      'strike.Collider:rayIntersections: x must be a finite number, got nil')
    expect.raisesAt(function() c:rayIntersections(0, 0, 0, 0) end,
      'strike.Collider:rayIntersections: the direction must not be zero')
    expect.raisesAt(function() c:rayIntersects(0, 0, nan, 0) end,
      'strike.Collider:rayIntersects: dx must be a finite number, got nan')
    expect.raisesAt(function() c:rayIntersects(0, 0, 0, 0) end,
      'strike.Collider:rayIntersects: the direction must not be zero')
    expect.raisesAt(function() c:rayCast(0, inf, 1, 0) end,
      'strike.Collider:rayCast: y must be a finite number, got inf')
    expect.raisesAt(function() c:rayCast(0, 0, 0, 0) end, 'strike.Collider:rayCast: the direction must not be zero')
    expect.raisesAt(function() c:rayCast(0, 0, 1, 0, -0.5) end,
      'strike.Collider:rayCast: maxDistance must be a number >= 0 or nil, got -0.5')
    expect.raisesAt(function() c:segmentCast(0, 0, 1, nil) end,
      'strike.Collider:segmentCast: y2 must be a finite number, got nil')
    expect.raisesAt(function() T.Collider():rayCast(0, 0, 0, nil) end,
      'strike.Collider:rayCast: dy must be a finite number, got nil')
  end)
end)

-- Allocation: the same method as spec/alloc_spec.lua (kilobytes with the GC stopped, the
-- least of three windows, interpreted on LuaJIT).
local alloc = require('spec.helpers.alloc')
local nothingPerCall = alloc.nothingPerCall
-- (a shorter warm-up than alloc_spec's: this file measures many paths)
local function kbPer(fn, n) return alloc.kbPer(fn, n, 2000) end

describe('ray allocation', function()
  setup(alloc.jitOff)
  teardown(alloc.jitOn)

  local shapes = {
    polygon = H.RegularPolygon(0, 0, 8, 2, 0.3),
    rectangle = H.Rectangle(0, 0, 4, 2),
    circle = H.Circle(0, 0, 2),
    edge = H.Edge(-1, -2, 1, 2),
  }
  local c = T.Collider(H.Rectangle(0, 0, 2, 2), T.Collider(H.Circle(5, 0, 1)), H.Edge(10, -1, 10, 1))
  local ts = {}

  it('rayIntersects, rayIntersections with ts, rayCast and segmentCast allocate nothing on shapes', function()
    for name, s in pairs(shapes) do
      for k, r in ipairs({ { -5, 0.1, 1, 0 }, { 0, 0, 0.3, 1 } }) do -- from outside, from inside
        local x, y, dx, dy = r[1], r[2], r[3], r[4]
        local what = ('%s ray (%g, %g, %g, %g): '):format(name, x, y, dx, dy)
        nothingPerCall(kbPer(function() s:rayIntersects(x, y, dx, dy) end, 10000), what .. 'rayIntersects')
        nothingPerCall(kbPer(function() s:rayIntersections(x, y, dx, dy, ts) end, 10000), what .. 'rayIntersections')
        if k == 1 then
          nothingPerCall(kbPer(function() s:rayCast(x, y, dx, dy) end, 10000), what .. 'rayCast')
        else
          nothingPerCall(kbPer(function() s:rayCast(x, y, dx, dy, 100) end, 10000), what .. 'rayCast, maxDistance')
        end
        nothingPerCall(kbPer(function() s:segmentCast(x, y, x + 10 * dx, y + 10 * dy) end, 10000),
          what .. 'segmentCast')
      end
      -- a miss, which empties ts
      nothingPerCall(kbPer(function() s:rayIntersections(-5, 9, 1, 0, ts) end, 10000),
        name .. ' miss: rayIntersections')
    end
  end)

  it('rayIntersects, rayCast and segmentCast allocate nothing on colliders', function()
    for _, r in ipairs({ { -5, 0, 1, 0 }, { 20, 0, -1, 0 }, { -5, 9, 1, 0 } }) do
      local x, y, dx, dy = r[1], r[2], r[3], r[4]
      local what = ('collider ray (%g, %g, %g, %g): '):format(x, y, dx, dy)
      nothingPerCall(kbPer(function() c:rayIntersects(x, y, dx, dy) end, 10000), what .. 'rayIntersects')
      nothingPerCall(kbPer(function() c:rayCast(x, y, dx, dy) end, 10000), what .. 'rayCast')
      nothingPerCall(kbPer(function() c:segmentCast(x, y, x + 30 * dx, y + 30 * dy) end, 10000), what .. 'segmentCast')
    end
  end)

  it('a moved shape is refreshed once, without allocating', function()
    local s = shapes.polygon
    nothingPerCall(kbPer(function()
      s:translate(0.001, 0)
      s:rayCast(-5, 0, 1, 0)
      c:translate(0.001, 0)
      c:rayCast(-5, 0, 1, 0)
    end, 10000), 'moving then casting')
  end)
end)
