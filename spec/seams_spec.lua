-- Seams: the cuts between the pieces of an S.trikers.Concave are inside it, not surfaces
-- (`_seams` on the pieces, strike/base/VertexShape.lua). containsPoint, the ray queries,
-- nesting, transforms, consolidate and copies. Random outlines are in
-- spec/property/seams_property_spec.lua.
local S = require('strike')
local expect = require('spec.helpers.expect')

local H, T = S.hapes, S.trikers
local near = expect.near
local cos, sin = math.cos, math.sin

-- The L of the examples: a 100 x 20 foot and a 20 x 100 upright, sharing the 20 x 20 corner.
local L_OUTLINE = { 0, 0, 100, 0, 100, 20, 20, 20, 20, 100, 0, 100 }
local function newL() return T.Concave(L_OUTLINE) end
-- A T: a 30 x 10 bar, a 10 x 20 stem on its middle third.
local T_OUTLINE = { 0, 0, 30, 0, 30, 10, 20, 10, 20, 30, 10, 30, 10, 10, 0, 10 }

-- Strictly inside the L (an independent description of it).
local function inL(x, y)
  return x > 0 and y > 0 and ((x < 100 and y < 20) or (x < 20 and y < 100))
end

-- The seam value of the face of `shape` from (x1, y1) to (x2, y2) (within 1e-9); errors
-- when the shape has no such face.
local function seamOf(shape, x1, y1, x2, y2)
  for i = 1, shape:getVertexCount() do
    local a, b, c, d = shape:getEdge(i)
    if math.abs(a - x1) + math.abs(b - y1) + math.abs(c - x2) + math.abs(d - y2) < 1e-9 then
      return shape._seams and shape._seams[i] or false
    end
  end
  error(('no face (%g, %g) -> (%g, %g)'):format(x1, y1, x2, y2))
end

-- Set `_seams` on a hand-made piece from a list of faces { x1, y1, x2, y2, seam }.
local function setSeams(shape, faces)
  local seams = {}
  for i = 1, shape:getVertexCount() do seams[i] = false end
  for _, f in ipairs(faces) do
    local done = false
    for i = 1, shape:getVertexCount() do
      local a, b, c, d = shape:getEdge(i)
      if math.abs(a - f[1]) + math.abs(b - f[2]) + math.abs(c - f[3]) + math.abs(d - f[4]) < 1e-9 then
        seams[i], done = f[5], true
      end
    end
    assert(done, 'setSeams: no such face')
  end
  shape._seams = seams
  return shape
end

-- Every seam face of a collider's leaves, as { x1, y1, x2, y2 } lists.
local function seamFaces(c)
  local out = {}
  for s in c:elems() do
    for i = 1, s:getVertexCount() do
      if s._seams and s._seams[i] then out[#out + 1] = { s:getEdge(i) } end
    end
  end
  return out
end

-- The distances of rayIntersections, all leaves together, ascending (an empty list on nil).
local function crossings(c, x, y, dx, dy)
  local res, out = c:rayIntersections(x, y, dx, dy), {}
  if res then
    for shape, ts in pairs(res) do
      assert.truthy(#ts >= 1)
      local found = false
      for s in c:elems() do found = found or s == shape end
      assert.is_true(found)
      for i = 1, #ts do out[#out + 1] = ts[i] end
    end
  end
  table.sort(out)
  return out
end

local function nearList(got, want, tol)
  assert.equals(#want, #got, ('expected %d crossings, got %d'):format(#want, #got))
  for i = 1, #want do near(got[i], want[i], tol or 1e-9) end
end

-- Does the shape have the edge (x1, y1) -> (x2, y2)?
local function hasEdge(shape, x1, y1, x2, y2)
  return pcall(seamOf, shape, x1, y1, x2, y2)
end

describe('Concave seams: the flags', function()
  it('marks the one diagonal of the L, on both pieces, and nothing else', function()
    local l = newL()
    assert.equals(2, select('#', l:unpack()))
    local faces = seamFaces(l)
    assert.equals(2, #faces)
    for _, f in ipairs(faces) do
      -- the diagonal from (0, 0) to the reflex vertex (20, 20), one way on each piece
      local a = { f[1], f[2], f[3], f[4] }
      if a[1] > a[3] then a = { a[3], a[4], a[1], a[2] } end
      expect.nearList(a, { 0, 0, 20, 20 }, 1e-12)
    end
  end)

  it('gives the same flags for the other winding and with collinear points in the outline', function()
    for _, c in ipairs({
      T.Concave(0, 100, 20, 100, 20, 20, 100, 20, 100, 0, 0, 0),
      T.Concave(0, 0, 50, 0, 100, 0, 100, 20, 60, 20, 20, 20, 20, 100, 0, 100, 0, 50),
    }) do
      local faces = seamFaces(c)
      assert.equals(2, #faces)
      for _, f in ipairs(faces) do near(math.abs(f[1] - f[3]) + math.abs(f[2] - f[4]), 40, 1e-12) end
    end
  end)

  it('leaves a convex outline as one piece without seams', function()
    local c = T.Concave(0, 0, 10, 0, 10, 10, 0, 10)
    assert.equals(1, select('#', c:unpack()))
    assert.is_false((c:unpack())._seams)
    assert.is_false(H.Rectangle(0, 0, 1, 1)._seams)
  end)

  it('marks a face that is outline, cut, outline by the parts under the cut (the bar of a T)', function()
    local t = T.Concave(T_OUTLINE)
    assert.equals(2, select('#', t:unpack()))
    local bar, stem = (t:unpack()), select(2, t:unpack())
    if stem:getArea() > bar:getArea() then bar, stem = stem, bar end
    -- the bar's top face runs from (30, 10) to (0, 10): cut from x = 20 to x = 10
    local top = seamOf(bar, 30, 10, 0, 10)
    assert.equals('table', type(top))
    expect.nearList(top, { 1 / 3, 2 / 3 }, 1e-12)
    assert.is_true(seamOf(stem, 10, 10, 20, 10))
    assert.is_false(seamOf(bar, 0, 0, 30, 0))
    assert.is_false(seamOf(stem, 20, 30, 10, 30))
  end)

  it('marks a comb\'s bar under each of its teeth, parts that touch at outline vertices apart', function()
    -- a bar 0..50 x 0..10 with teeth on 0..10, 20..30 and 40..50 and gaps between them
    local comb = T.Concave(0, 0, 50, 0, 50, 20, 40, 20, 40, 10, 30, 10, 30, 20, 20, 20, 20, 10, 10, 10,
      10, 20, 0, 20)
    -- whatever the pieces, the seams are exactly the three tooth bases: x in (0, 10), (20, 30),
    -- (40, 50) at y = 10, and the diagonals
    for x = 0.5, 49.5, 1 do
      local tooth = (x < 10) or (x > 20 and x < 30) or (x > 40)
      assert.equals(tooth, comb:containsPoint(x, 10), 'x = ' .. x)
    end
    for _, x in ipairs({ 0, 10, 20, 30, 40, 50 }) do assert.is_false(comb:containsPoint(x, 10)) end
  end)
end)

describe('Concave seams: containsPoint', function()
  it('holds every one of the 3,401 integer points strictly inside the L', function()
    local l, count, missed = newL(), 0, {}
    for x = -1, 101 do
      for y = -1, 101 do
        if inL(x, y) then
          count = count + 1
          if not l:containsPoint(x, y) then missed[#missed + 1] = ('(%d, %d)'):format(x, y) end
        else
          assert.is_false(l:containsPoint(x, y), ('(%d, %d) is not inside the L'):format(x, y))
        end
      end
    end
    assert.equals(3401, count)
    assert.equals('', table.concat(missed, ' '))
  end)

  it('holds the points of the diagonal between its ends, not its ends', function()
    local l = newL()
    for k = 1, 19 do
      assert.is_true(l:containsPoint(k, k))
      assert.is_true(l:containsPoint(k + 0.5, k + 0.5))
      assert.is_true(l:containsPoint({ x = k + 0.25, y = k + 0.25 }))
    end
    assert.is_true(l:containsPoint(1e-9, 1e-9))
    assert.is_true(l:containsPoint(20 - 1e-9, 20 - 1e-9))
    assert.is_false(l:containsPoint(0, 0))
    assert.is_false(l:containsPoint(20, 20))
    -- beside the diagonal, a hair outside either piece, is inside one of them
    assert.is_true(l:containsPoint(10, 10 + 1e-9))
    assert.is_true(l:containsPoint(10, 10 - 1e-9))
  end)

  it('leaves every point of the outline outside', function()
    local l = newL()
    for i = 1, 6 do
      local j = i % 6 + 1
      local x1, y1, x2, y2 = L_OUTLINE[2 * i - 1], L_OUTLINE[2 * i], L_OUTLINE[2 * j - 1], L_OUTLINE[2 * j]
      for k = 0, 400 do
        local x, y = x1 + (x2 - x1) * k / 400, y1 + (y2 - y1) * k / 400
        assert.is_false(l:containsPoint(x, y), ('(%.17g, %.17g) is on the outline'):format(x, y))
      end
    end
  end)

  it('follows a T: inside on the cut under the stem, outside on the bar\'s outline', function()
    local t = T.Concave(T_OUTLINE)
    for x = 0, 30, 0.5 do
      assert.equals(x > 10 and x < 20, t:containsPoint(x, 10), 'x = ' .. x)
    end
    for x = 1, 29 do
      for y = 1, 29 do
        local inside = (y < 10) or (y == 10 and x > 10 and x < 20) or (x > 10 and x < 20 and y < 30)
        assert.equals(inside, t:containsPoint(x, y), ('(%d, %d)'):format(x, y))
      end
    end
  end)
end)

describe('Concave seams: rays', function()
  it('rayCast from inside the L reports where it leaves the outline, not the diagonal', function()
    local l = newL()
    local d, x, y, nx, ny, shape = l:rayCast(5, 15, 1, 0)
    near(d, 95)
    near(x, 100)
    near(y, 15)
    near(nx, 1)
    near(ny, 0)
    assert.is_true(hasEdge(shape, 100, 0, 100, 20)) -- the piece that owns that outline edge
    -- the same up the upright, and toward the diagonal from the other piece
    d, x, y, nx, ny = l:rayCast(15, 5, 0, 1)
    near(d, 95)
    near(x, 15)
    near(y, 100)
    near(nx, 0)
    near(ny, 1)
    d, x, y, nx, ny = l:rayCast(50, 10, -1, 0)
    near(d, 50)
    near(x, 0)
    near(y, 10)
    near(nx, -1)
    near(ny, 0)
    -- within maxDistance only
    assert.is_nil(l:rayCast(5, 15, 1, 0, 94))
    near(l:rayCast(5, 15, 1, 0, 95), 95)
  end)

  it('rayCast from outside stops at the outline, whichever piece is met first', function()
    local l = newL()
    local d, x, y, nx, ny = l:rayCast(-10, 15, 1, 0)
    near(d, 10)
    near(x, 0)
    near(y, 15)
    near(nx, -1)
    near(ny, 0)
    -- from the notch into the L through the reflex vertex, which ends the diagonal too: the
    -- vertex is the outline point met
    d, x, y = l:rayCast(50, 40, -3, -2)
    near(d, math.sqrt(1300))
    near(x, 20)
    near(y, 20)
    -- from the notch the other way: nothing
    assert.is_nil(l:rayCast(50, 50, 1, 1))
  end)

  it('rayIntersections gives exactly the outline crossings of a ray across the whole L', function()
    local l = newL()
    for _, y in ipairs({ 0.5, 1, 5, 10, 15, 19, 19.5 }) do
      nearList(crossings(l, -10, y, 1, 0), { 10, 110 })
      nearList(crossings(l, -10, y, 3, 0), { 10, 110 }) -- (the direction's length does not matter)
    end
    for _, y in ipairs({ 20.5, 50, 99 }) do nearList(crossings(l, -10, y, 1, 0), { 10, 30 }) end
    for _, x in ipairs({ 1, 10, 19 }) do nearList(crossings(l, x, -10, 0, 1), { 10, 110 }) end
    -- from far away (the queries move the origin near the shape first): the same crossings
    nearList(crossings(l, -1e9, 10, 1, 0), { 1e9, 1e9 + 100 }, 1e-6)
    near(l:rayCast(-1e9, 10, 1, 0), 1e9, 1e-6)
    nearList(crossings(l, 10, 1e12, 0, -1), { 1e12 - 100, 1e12 }, 1e-3)
    -- from inside: the exit only
    nearList(crossings(l, 5, 10, 1, 0), { 95 })
    nearList(crossings(l, 5, 10, -1, 0), { 5 })
    -- a piece whose only crossing is on the diagonal is absent: the ray from (15, 18) toward
    -- -y leaves the upright piece through the diagonal, into the foot, which it leaves at y = 0
    local res = l:rayIntersections(15, 18, 0, -1)
    local n = 0
    for shape, ts in pairs(res) do
      n = n + 1
      assert.equals(1, #ts)
      near(ts[1], 18)
      assert.is_true(hasEdge(shape, 0, 0, 100, 0))
    end
    assert.equals(1, n)
    assert.is_nil(l:rayIntersections(50, 50, 1, 1))
  end)

  it('rayIntersections across the stem and bar of a T skips the cut', function()
    local t = T.Concave(T_OUTLINE)
    nearList(crossings(t, 15, 50, 0, -1), { 20, 50 }) -- the stem's top, the bar's bottom
    nearList(crossings(t, 5, 50, 0, -1), { 40, 50 }) -- the bar's top (outline there)
    local d, _, y, nx, ny = t:rayCast(5, 50, 0, -1)
    near(d, 40)
    near(y, 10)
    near(nx, 0)
    near(ny, 1)
    d, _, y = t:rayCast(15, 20, 0, -1)
    near(d, 20)
    near(y, 0)
  end)

  it('rayIntersects counts outline crossings only, and a ray from inside always leaves', function()
    local l = newL()
    for _, dir in ipairs({ { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 }, { 1, 1 }, { -1, -1 }, { 3, -1 } }) do
      assert.is_true(l:rayIntersects(5, 15, dir[1], dir[2]))
    end
    for _, dir in ipairs({ { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 }, { 3, -1 }, { -1, 3 } }) do
      assert.is_true(l:rayIntersects(10, 10, dir[1], dir[2])) -- (from the diagonal, across it)
    end
    assert.is_true(l:rayIntersects(-10, 15, 1, 0))
    assert.is_false(l:rayIntersects(-10, 15, -1, 0))
    assert.is_false(l:rayIntersects(50, 50, 1, 1))
    assert.is_false(l:rayIntersects(50, 50, 0, 1))
  end)

  it('segmentCast stops at the outline only', function()
    local l = newL()
    local d, x, y, nx, ny, shape = l:segmentCast(5, 15, 200, 15)
    near(d, 95)
    near(x, 100)
    near(y, 15)
    near(nx, 1)
    near(ny, 0)
    assert.is_true(hasEdge(shape, 100, 0, 100, 20))
    assert.is_nil(l:segmentCast(5, 15, 50, 15)) -- (it crosses the diagonal, inside the L)
    assert.is_nil(l:segmentCast(5, 15, 99, 15))
    d = l:segmentCast(-5, 15, 50, 15)
    near(d, 5)
  end)

  it('agrees across the four ray queries on a piece whose seams face nothing', function()
    -- (a hand-made piece: a square whose left and right faces are seams, alone in a collider)
    local sq = setSeams(H.Rectangle(5, 5, 10, 10), { { 10, 0, 10, 10, true }, { 0, 10, 0, 0, true } })
    local c = T.Collider(sq)
    -- across both seams: no hit at all
    assert.is_false(c:rayIntersects(-5, 5, 1, 0))
    assert.is_nil(c:rayCast(-5, 5, 1, 0))
    assert.is_nil(c:rayIntersections(-5, 5, 1, 0))
    assert.is_nil(c:segmentCast(-5, 5, 20, 5))
    -- in through a seam, out through the top: one hit
    assert.is_true(c:rayIntersects(-5, 0, 1, 1))
    near(c:rayCast(-5, 0, 1, 1), 10 * math.sqrt(2))
    nearList(crossings(c, -5, 0, 1, 1), { 10 * math.sqrt(2) })
  end)

  it('leaves the pieces\' own queries alone: a piece by itself still ends at its diagonal', function()
    local l = newL()
    local upright
    for s in l:elems() do
      if s:containsPoint(5, 15) then upright = s end
    end
    near(upright:rayCast(5, 15, 1, 0), 10)
    assert.is_false(upright:containsPoint(10, 10))
  end)
end)

describe('Concave seams: nesting, transforms, copies, consolidate', function()
  it('works for a Concave nested in other colliders', function()
    local l = newL()
    local inner = T.Collider(l)
    local outer = T.Collider(H.Circle(300, 300, 5), inner)
    for k = 1, 19 do assert.is_true(outer:containsPoint(k, k)) end
    assert.is_false(outer:containsPoint(20, 20))
    local d, x, _, _, _, shape = outer:rayCast(5, 15, 1, 0)
    near(d, 95)
    near(x, 100)
    assert.is_true(hasEdge(shape, 100, 0, 100, 20))
    nearList(crossings(outer, -10, 10, 1, 0), { 10, 110 })
    assert.is_nil(outer:segmentCast(5, 15, 50, 15))
  end)

  it('survives rotation, scaling and translation: the flags are per face', function()
    local l = newL()
    local before = {}
    for s in l:elems() do before[s] = s._seams end
    local cx, cy = l:getCentroid()
    local a, k, tx, ty = 0.7, 2.5, 1000, -300
    l:rotate(a):scale(k):translate(tx, ty)
    for s in l:elems() do assert.equals(before[s], s._seams) end
    local c, s = cos(a), sin(a)
    local function map(x, y)
      local dx, dy = (x - cx) * k, (y - cy) * k
      return cx + c * dx - s * dy + tx, cy + s * dx + c * dy + ty
    end
    -- every integer point inside, the diagonal included
    for x = 1, 99 do
      for y = 1, 99 do
        if inL(x, y) then assert.is_true(l:containsPoint(map(x, y)), ('(%d, %d)'):format(x, y)) end
      end
    end
    -- just outside the outline: out (the outline itself is only as exact as the transform)
    for _, p in ipairs({ { 50, -1e-6 }, { 100 + 1e-6, 10 }, { 60, 20 + 1e-6 }, { 20 + 1e-6, 60 },
      { -1e-6, 50 }, { 10, 100 + 1e-6 }, { 20 + 1e-6, 20 + 1e-6 } }) do
      assert.is_false(l:containsPoint(map(p[1], p[2])))
    end
    -- the ray from (5, 15) along +x, carried along
    local ox, oy = map(5, 15)
    local d, x, y, nx, ny = l:rayCast(ox, oy, c, s)
    near(d, 95 * k, 1e-9)
    local ex, ey = map(100, 15)
    near(x, ex, 1e-9)
    near(y, ey, 1e-9)
    near(nx, c, 1e-12)
    near(ny, s, 1e-12)
    local px, py = map(-10, 10)
    nearList(crossings(l, px, py, c, s), { 10 * k, 110 * k }, 1e-9)
  end)

  it('copies keep the flags: collider:copy() and shape:copy()', function()
    local l = newL()
    local c = l:copy(500, 500, 1)
    for i = 1, 2 do assert.equals(select(i, l:unpack())._seams, select(i, c:unpack())._seams) end
    local piece = (l:unpack()):copy()
    assert.equals((l:unpack())._seams, piece._seams)
    local plain = l:copy()
    for k = 1, 19 do assert.is_true(plain:containsPoint(k, k)) end
    near(plain:rayCast(5, 15, 1, 0), 95)
    -- the moved copy too: its centroid at (500, 500), turned by 1 radian
    local cx, cy = l:getCentroid()
    local cs, sn = cos(1), sin(1)
    for kk = 1, 19 do
      local dx, dy = kk - cx, kk - cy
      assert.is_true(c:containsPoint(500 + cs * dx - sn * dy, 500 + sn * dx + cs * dy))
    end
  end)

  it('a piece removed from its Concave keeps its flags (they describe its place in it)', function()
    local l = newL()
    local flags = (l:unpack())._seams
    local piece = l:remove(1)
    assert.equals(flags, piece._seams)
    assert.truthy(piece._seams)
  end)

  it('ConvexPolygon:merge keeps the seams of the faces that remain; the shared one goes', function()
    -- the bar of the T as two triangles cut along its diagonal, with the T's stem above
    local lower = setSeams(H.ConvexPolygon(0, 0, 30, 0, 30, 10), { { 30, 10, 0, 0, true } })
    local upper = setSeams(H.ConvexPolygon(0, 0, 30, 10, 0, 10),
      { { 0, 0, 30, 10, true }, { 30, 10, 0, 10, { 1 / 3, 2 / 3 } } })
    local bar = lower:merge(upper)
    assert.truthy(bar)
    assert.equals(4, bar:getVertexCount())
    expect.nearList(seamOf(bar, 30, 10, 0, 10), { 1 / 3, 2 / 3 }, 1e-12)
    assert.is_false(seamOf(bar, 0, 0, 30, 0))
    assert.is_false(seamOf(bar, 30, 0, 30, 10))
    assert.is_false(seamOf(bar, 0, 10, 0, 0))
    -- pieces without seams merge into one without
    assert.is_false(H.ConvexPolygon(0, 0, 1, 0, 1, 1):merge(H.ConvexPolygon(0, 0, 1, 1, 0, 1))._seams)
    -- a whole seam face and a partial one meeting at a vertex on one line stay two parts
    local a = setSeams(H.ConvexPolygon(0, 0, 10, 0, 10, 10), { { 0, 0, 10, 0, true } })
    local b = setSeams(H.ConvexPolygon(10, 0, 20, 0, 10, 10), { { 10, 0, 20, 0, { 0, 0.5 } } })
    local m = a:merge(b)
    expect.nearList(seamOf(m, 0, 0, 20, 0), { 0, 0.5, 0.5, 0.75 }, 1e-12)
    -- two whole seams on one line: two parts, and the vertex between them (an outline vertex
    -- in a compound: two cuts meet there) is not inside
    b = setSeams(H.ConvexPolygon(10, 0, 20, 0, 10, 10), { { 10, 0, 20, 0, true } })
    m = a:merge(b)
    expect.nearList(seamOf(m, 0, 0, 20, 0), { 0, 0.5, 0.5, 1 }, 1e-12)
    local c = T.Collider(m)
    assert.is_true(c:containsPoint(5, 0))
    assert.is_true(c:containsPoint(15, 0))
    assert.is_false(c:containsPoint(10, 0))
    assert.is_false(c:containsPoint(0, 0))
  end)

  it('consolidate merges two pieces across their seam and the compound stays one solid', function()
    local lower = setSeams(H.ConvexPolygon(0, 0, 30, 0, 30, 10), { { 30, 10, 0, 0, true } })
    local upper = setSeams(H.ConvexPolygon(0, 0, 30, 10, 0, 10),
      { { 0, 0, 30, 10, true }, { 30, 10, 0, 10, { 1 / 3, 2 / 3 } } })
    local stem = setSeams(H.ConvexPolygon(10, 10, 20, 10, 20, 30, 10, 30), { { 10, 10, 20, 10, true } })
    local c = T.Collider(lower, upper, stem)
    assert.is_true(c:containsPoint(15, 5)) -- (on the cut from (0, 0) to (30, 10))
    assert.is_true(c:containsPoint(6, 2))
    nearList(crossings(c, -10, 2, 1, 0), { 10, 40 })
    c:consolidate()
    assert.equals(2, c:getShapeCount())
    local bar = (c:unpack())
    expect.nearList(seamOf(bar, 30, 10, 0, 10), { 1 / 3, 2 / 3 }, 1e-12)
    assert.is_true(c:containsPoint(6, 2))
    assert.is_true(c:containsPoint(15, 10))
    assert.is_false(c:containsPoint(5, 10))
    nearList(crossings(c, 15, 50, 0, -1), { 20, 50 })
    nearList(crossings(c, -10, 2, 1, 0), { 10, 40 })
    near(c:rayCast(15, 20, 0, -1), 20)
  end)
end)
