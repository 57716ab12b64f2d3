local S = require('strike')
local expect = require('spec.helpers.expect')
local near, raisesAt = expect.near, expect.raisesAt
local H = S.hapes

-- The points of a manifold as { {x, y, depth}, ... } sorted by x then y.
local function pointsOf(c)
  local list = {}
  for i = 1, c.count do list[i] = { c[i].x, c[i].y, c[i].depth } end
  table.sort(list, function(a, b) if a[1] ~= b[1] then return a[1] < b[1] end return a[2] < b[2] end)
  return list
end

local function same(got, want)
  assert.equals(#want, #got)
  for i = 1, #want do
    for k = 1, 3 do near(got[i][k], want[i][k], 1e-9, ('point %d value %d'):format(i, k)) end
  end
end

describe('S.ite', function()
  -- the floor's top face is y = 0; y grows downward, so boxes above it have y < 0
  local function floor() return H.Rectangle(0, 5, 100, 10) end

  it('gives a box resting on a wider box 2 points at the ends of the overlap', function()
    local c = S.ite(S.AT(floor(), H.Rectangle(10, -4, 20, 10)))
    assert.equals(2, c.count)
    assert.equals(2, #c)
    near(c.nx, 0) near(c.ny, -1)
    same(pointsOf(c), { { 0, 0.5, 1 }, { 20, 0.5, 1 } }) -- midway between y = 0 and y = 1
  end)

  it('gives a small box on a big one its 2 bottom corners', function()
    same(pointsOf(S.ite(S.AT(floor(), H.Rectangle(0, -4.5, 4, 10)))), { { -2, 0.25, 0.5 }, { 2, 0.25, 0.5 } })
  end)

  it('clips a wide box on a narrow one to the narrow one', function()
    same(pointsOf(S.ite(S.AT(H.Rectangle(0, 5, 20, 10), H.Rectangle(0, -4, 100, 10)))),
      { { -10, 0.5, 1 }, { 10, 0.5, 1 } })
  end)

  it('gives a rotated box corner pressed into a face 1 point', function()
    local d = 5 * math.sqrt(2) - 6 -- how far the corner reaches below y = 0
    local c = S.ite(S.AT(floor(), H.Rectangle(0, -6, 10, 10, math.pi / 4)))
    assert.equals(1, c.count)
    same(pointsOf(c), { { 0, d / 2, d } })
  end)

  it('gives a circle on a box face 1 point, in either argument order', function()
    same(pointsOf(S.ite(S.AT(floor(), H.Circle(3, -4, 5)))), { { 3, 0.5, 1 } })
    local c = S.ite(S.AT(H.Circle(3, -4, 5), floor()))
    same(pointsOf(c), { { 3, 0.5, 1 } })
    near(c.ny, 1)
  end)

  it('gives two circles the point midway between their surfaces', function()
    same(pointsOf(S.ite(S.AT(H.Circle(0, 0, 5), H.Circle(8, 0, 5)))), { { 4, 0, 2 } })
    same(pointsOf(S.ite(S.AT(H.Circle(0, 0, 5), H.Circle(8, 0, 4)))), { { 4.5, 0, 1 } })
  end)

  it('handles an edge against a box', function()
    same(pointsOf(S.ite(S.AT(H.Edge(-50, 0, 50, 0), H.Rectangle(0, -4, 10, 10)))),
      { { -5, 0.5, 1 }, { 5, 0.5, 1 } })
    same(pointsOf(S.ite(S.AT(H.Rectangle(0, -4, 10, 10), H.Edge(-50, 0, 50, 0)))),
      { { -5, 0.5, 1 }, { 5, 0.5, 1 } })
  end)

  it('handles deep overlaps', function()
    same(pointsOf(S.ite(S.AT(H.Rectangle(0, 0, 10, 10), H.Rectangle(1, 1, 10, 10)))),
      { { 0.5, -4, 9 }, { 0.5, 5, 9 } })
    local c = S.ite(S.AT(H.Rectangle(0, 0, 10, 10), H.Rectangle(0, 0, 10, 10)))
    assert.equals(2, c.count)
    near(c[1].depth, 10)
  end)

  it('returns nil for a separating MTV', function()
    assert.is_nil(S.ite(S.AT(H.Rectangle(0, 0, 10), H.Rectangle(30, 0, 10))))
    assert.is_nil(S.ite(S.AT(H.Rectangle(0, 0, 10), H.Rectangle(10, 0, 10)))) -- touching
  end)

  it('works on S.triking results from compound colliders', function()
    -- (several members: the points are where the two touch once the box has moved by the
    -- MTV, on the floor's top face y = 0, not midway as for two shapes)
    local ground = S.trikers.Collider(H.Rectangle(0, 5, 100, 10), H.Circle(200, 0, 5))
    local m = S.triking(ground, S.trikers.Rectangle(0, -4.5, 4, 10))
    same(pointsOf(S.ite(m)), { { -2, 0, 0.5 }, { 2, 0, 0.5 } })
  end)

  it('keeps feature ids while the same features touch, and changes them when they change', function()
    local box = H.Rectangle(0, -4.5, 4, 10)
    local first = S.ite(S.AT(floor(), box))
    local ids = { first[1].id, first[2].id }
    box:translate(3, 0.2) -- slides and sinks: same faces, same corners
    local second = S.ite(S.AT(floor(), box))
    assert.same(ids, { second[1].id, second[2].id })
    box:translateTo(49, -4.5) -- now partly off the floor's end: a corner is cut by a side plane
    local third = S.ite(S.AT(floor(), box))
    assert.equals(2, third.count)
    assert.are_not.same(ids, { third[1].id, third[2].id })
    assert.is_number(third[1].id)
  end)

  it('fills an out table, reusing its point tables, and keeps #out equal to the count', function()
    local out = {}
    local two = S.ite(S.AT(floor(), H.Rectangle(0, -4.5, 4, 10)), out)
    assert.equals(out, two)
    local p1, p2 = out[1], out[2]
    local one = S.ite(S.AT(floor(), H.Circle(3, -4, 5)), out)
    assert.equals(out, one)
    assert.equals(1, #out)
    assert.equals(p1, out[1])
    S.ite(S.AT(floor(), H.Rectangle(0, -4.5, 4, 10)), out)
    assert.equals(p2, out[2])
  end)

  it('keeps #out equal to the count after a compound\'s 4 points, and reuses their tables', function()
    local out = {}
    local L = S.trikers.Collider(H.Rectangle(50, 10, 100, 20), H.Rectangle(10, 50, 20, 100))
    local box = H.Rectangle(22, 22, 10, 10)
    S.ite(S.triking(L, box), out)
    assert.equals(4, #out)
    local tables = {}
    for i = 1, 4 do tables[out[i]] = true end
    local function reused(c)
      for i = 1, c.count do assert(tables[c[i]], 'a new point table') end
    end
    local two = S.ite(S.AT(floor(), H.Rectangle(0, -4.5, 4, 10)), out)
    assert.same({ 2, 2 }, { two.count, #two })
    reused(two)
    local one = S.ite(S.AT(floor(), H.Circle(3, -4, 5)), out)
    assert.same({ 1, 1 }, { one.count, #one })
    reused(one)
    local four = S.ite(S.triking(L, box), out)
    assert.same({ 4, 4 }, { four.count, #four })
    reused(four)
  end)

  it('gives every point its normal: between two shapes the MTV\'s, also in an out table a compound filled', function()
    local out = {}
    -- a compound's points first: the box [17, 27]^2 in the corner of an L, normals (0, 1), (1, 0)
    local L = S.trikers.Collider(H.Rectangle(50, 10, 100, 20), H.Rectangle(10, 50, 20, 100))
    local c = S.ite(S.triking(L, H.Rectangle(22, 22, 10, 10)), out)
    assert.equals(4, c.count)
    -- then a circle against a box's corner region: the normal along the centre line (3, 4) / 5
    c = S.ite(S.AT(H.Rectangle(0, 0, 10), H.Circle(5 + 2.4, 5 + 3.2, 5)), out)
    assert.equals(1, c.count)
    near(c.nx, 0.6, 1e-12)
    near(c.ny, 0.8, 1e-12)
    assert.equals(c.nx, c[1].nx)
    assert.equals(c.ny, c[1].ny)
    -- and two points on a floor, each with the floor's normal (0, -1)
    c = S.ite(S.AT(floor(), H.Rectangle(0, -4.5, 4, 10)), out)
    for i = 1, 2 do assert.same({ 0, -1 }, { c[i].nx, c[i].ny }) end
  end)

  it('rejects what is not an MTV from S.AT or S.triking', function()
    raisesAt(function() S.ite(nil) end, 'strike.ite: argument 1 must be an MTV, got nil')
    raisesAt(function() S.ite(S.MTV(1, 0)) end, 'strike.ite: the MTV must come from S.AT or S.triking')
    raisesAt(function() S.ite(S.AT(floor(), floor()), 5) end, 'strike.ite: argument 2 (out) must be a table')
  end)
end)
