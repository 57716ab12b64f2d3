local S = require('strike')
local expect = require('spec.helpers.expect')
local near, nearList, raisesAt = expect.near, expect.nearList, expect.raisesAt
local pi = math.pi

local function verts(s) return (s:getVertices()) end
local function bbox(s) return { s:getBbox() } end

describe('S.hapes', function()
  it('holds the six documented shape classes', function()
    for _, name in ipairs({ 'ConvexPolygon', 'Circle', 'Edge', 'Ellipse', 'Rectangle', 'RegularPolygon' }) do
      assert.is_table(S.hapes[name], name)
      assert.equals(name, S.hapes[name].name)
    end
  end)

  it('returns nil for names it does not have', function()
    assert.is_nil(S.hapes.NoSuchShape)
    assert.is_nil(S.hapes['not a name'])
  end)
end)

describe('ConvexPolygon', function()
  it('accepts any order and winding and stores positive winding from the first point', function()
    local ccw = S.hapes.ConvexPolygon(0, 0, 10, 0, 10, 10, 0, 10)
    local cw = S.hapes.ConvexPolygon(0, 0, 0, 10, 10, 10, 10, 0)
    local shuffled = S.hapes.ConvexPolygon(10, 10, 0, 0, 10, 0, 0, 10)
    nearList(verts(ccw), { 0, 0, 10, 0, 10, 10, 0, 10 })
    nearList(verts(cw), { 0, 0, 10, 0, 10, 10, 0, 10 })
    nearList(verts(shuffled), { 10, 10, 0, 10, 0, 0, 10, 0 })
    for _, p in ipairs({ ccw, cw, shuffled }) do
      assert.equals(100, p:getArea())
      local x, y = p:getCentroid()
      near(x, 5) near(y, 5)
    end
  end)

  it('accepts one table of coordinates', function()
    local p = S.hapes.ConvexPolygon({ 0, 0, 4, 0, 0, 3 })
    assert.equals(6, p:getArea())
    assert.equals(3, p:getVertexCount())
  end)

  it('drops duplicate and collinear points', function()
    local p = S.hapes.ConvexPolygon(0, 0, 5, 0, 10, 0, 10, 0, 10, 10, 0, 10, 0, 5, 0, 0)
    assert.equals(4, p:getVertexCount())
    assert.equals(100, p:getArea())
  end)

  it('gives an area that is never negative, whatever the winding', function()
    assert.equals(6, S.hapes.ConvexPolygon(0, 0, 0, 3, 4, 0):getArea())
  end)

  it('computes the area centroid, not the vertex mean', function()
    local p = S.hapes.ConvexPolygon(0, 0, 10, 0, 10, 10, 0, 10, -1, 5) -- a pentagon
    local a, x, y = p:getAreaCentroid()
    assert.equals(105, a)
    near(y, 5)
    near(x, (100 * 5 + 5 * (-1 / 3)) / 105)
  end)

  it('rejects fewer than 3 distinct non-collinear points', function()
    raisesAt(function() S.hapes.ConvexPolygon(0, 0, 1, 1) end, 'needs at least 3 distinct non-collinear points, got 2')
    raisesAt(function() S.hapes.ConvexPolygon(0, 0, 1, 1, 2, 2) end, 'got 3 distinct points, all collinear')
    raisesAt(function() S.hapes.ConvexPolygon(1, 1, 1, 1, 1, 1) end, 'got 1 distinct point')
  end)

  it('rejects concave input and points to S.trikers.Concave', function()
    raisesAt(function() S.hapes.ConvexPolygon(0, 0, 10, 0, 10, 10, 5, 2, 0, 10) end, 'S.trikers.Concave')
  end)

  it('rejects NaN, infinite and non-number values and odd counts', function()
    raisesAt(function() S.hapes.ConvexPolygon(0, 0, 0 / 0, 1, 1, 0) end, 'x2 must be a finite number, got nan')
    raisesAt(function() S.hapes.ConvexPolygon(0, 0, 1, math.huge, 1, 0) end, 'y2 must be a finite number, got inf')
    raisesAt(function() S.hapes.ConvexPolygon(0, 0, '1', 1, 1, 0) end, 'x2 must be a finite number, got string')
    raisesAt(function() S.hapes.ConvexPolygon(0, 0, 1, 1, 1) end, 'odd number of values (5)')
    raisesAt(function() S.hapes.ConvexPolygon() end, 'got 0 distinct points')
  end)

  it('rejects coordinates so large that the area overflows', function()
    raisesAt(function() S.hapes.ConvexPolygon(0, 0, 1e300, 0, 0, 1e300) end, 'strike.ConvexPolygon: too large')
  end)
end)

describe('ConvexPolygon coordinates, given as arguments or as a table', function()
  local unpack = table.unpack or unpack -- luacheck: ignore 113 143
  -- (up to 64 values are read one pair at a time, more are packed first: both ways alike)
  for _, n in ipairs({ 3, 32, 33, 40 }) do
    it(n .. ' vertices', function()
      local t = {}
      for i = 1, n do
        local a = 2 * math.pi * i / n
        t[2 * i - 1], t[2 * i] = 10 * math.cos(a), 10 * math.sin(a)
      end
      local a, b = S.hapes.ConvexPolygon(unpack(t)), S.hapes.ConvexPolygon(t)
      assert.same({ b:getVertices() }, { a:getVertices() })
      t[2 * n] = 0 / 0
      local ok, err = pcall(S.hapes.ConvexPolygon, unpack(t))
      assert.is_false(ok)
      assert.truthy(tostring(err):find(('y%d must be a finite number, got nan'):format(n), 1, true))
      t[2 * n] = nil
      ok, err = pcall(S.hapes.ConvexPolygon, unpack(t, 1, 2 * n - 1))
      assert.is_false(ok)
      assert.truthy(tostring(err):find(('got an odd number of values (%d)'):format(2 * n - 1), 1, true))
    end)
  end
end)

describe('Rectangle', function()
  it('is centred, with edge 1 on the min-y side', function()
    local r = S.hapes.Rectangle(10, 20, 4, 2)
    nearList(verts(r), { 8, 19, 12, 19, 12, 21, 8, 21 })
    nearList({ r:getEdge(1) }, { 8, 19, 12, 19 })
    nearList({ r:getNormal(1) }, { 0, -1 })
    assert.equals(8, r:getArea())
    nearList(bbox(r), { 8, 19, 4, 2 })
  end)

  it('defaults the height to the width', function()
    assert.equals(9, S.hapes.Rectangle(0, 0, 3):getArea())
  end)

  it('takes an angle', function()
    local r = S.hapes.Rectangle(0, 0, 4, 2, pi / 2)
    nearList(bbox(r), { -1, -2, 2, 4 })
    near(r:getAngle(), pi / 2)
  end)

  it('validates its arguments', function()
    raisesAt(function() S.hapes.Rectangle(0, 0) end, 'strike.Rectangle: width must be a finite number > 0, got nil')
    raisesAt(function() S.hapes.Rectangle(0, 0, 1, -1) end, 'height must be a finite number > 0, got -1')
    raisesAt(function() S.hapes.Rectangle(nil, 0, 1) end, 'strike.Rectangle: x must be a finite number, got nil')
    raisesAt(function() S.hapes.Rectangle(0, 0, 1, 1, 0 / 0) end, 'angle must be a finite number, got nan')
  end)
end)

describe('RegularPolygon', function()
  it('puts vertex n at (x, y + r), in positive winding', function()
    local p = S.hapes.RegularPolygon(0, 0, 4, 10)
    nearList({ p:getVertex(4) }, { 0, 10 })
    near(p:getArea(), 200)
    assert.equals(4, p:getVertexCount())
  end)

  it('validates its arguments', function()
    raisesAt(function() S.hapes.RegularPolygon(0, 0, 2, 10) end, 'side count must be an integer from 3 to 4096, got 2')
    raisesAt(function() S.hapes.RegularPolygon(0, 0, 3.5, 10) end, 'got 3.5')
    raisesAt(function() S.hapes.RegularPolygon(0, 0, 5) end, 'radius must be a finite number > 0, got nil')
  end)
end)

describe('Ellipse', function()
  it('inscribes an n-gon with semi-axes a and b', function()
    local e = S.hapes.Ellipse(0, 0, 20, 10, 4)
    nearList(bbox(e), { -20, -10, 40, 20 })
    near(e:getArea(), 400)
  end)

  it('defaults the segment count to max(8, 4 * floor(a / b)), at most 64', function()
    assert.equals(8, S.hapes.Ellipse(0, 0, 10, 10):getVertexCount())
    assert.equals(12, S.hapes.Ellipse(0, 0, 30, 10):getVertexCount())
    assert.equals(64, S.hapes.Ellipse(0, 0, 1e6, 1):getVertexCount())
  end)

  it('validates its arguments', function()
    raisesAt(function() S.hapes.Ellipse(0, 0, 10) end, 'semi-axis b must be a finite number > 0, got nil')
    raisesAt(function() S.hapes.Ellipse() end, 'strike.Ellipse: x must be a finite number, got nil')
    raisesAt(function() S.hapes.Ellipse(0, 0, 1, 1, 2) end, 'segment count must be an integer from 3 to 4096')
  end)
end)

describe('Edge', function()
  it('is a segment with two edges, no area, and a bounding box', function()
    local e = S.hapes.Edge(0, 0, 10, 0)
    assert.equals(0, e:getArea())
    assert.equals(2, e:getVertexCount())
    nearList({ e:getEdge(1) }, { 0, 0, 10, 0 })
    nearList({ e:getEdge(2) }, { 10, 0, 0, 0 })
    nearList(bbox(e), { 0, 0, 10, 0 })
    nearList({ e:getCentroid() }, { 5, 0 })
    assert.equals(10, e:getLength())
    assert.is_false(e:containsPoint(5, 0))
  end)

  it('validates its arguments', function()
    raisesAt(function() S.hapes.Edge(1, 1, 1, 1) end, 'strike.Edge: the endpoints must differ')
    raisesAt(function() S.hapes.Edge(0, 0, 1) end, 'strike.Edge: y2 must be a finite number, got nil')
  end)
end)

describe('Circle', function()
  it('has a bounding box 2r wide, area pi r^2 and radius r', function()
    local c = S.hapes.Circle(10, 20, 5)
    nearList(bbox(c), { 5, 15, 10, 10 })
    near(c:getArea(), 25 * pi)
    assert.equals(5, c:getRadius())
  end)

  it('has no vertices or edges, without erroring', function()
    local c = S.hapes.Circle(0, 0, 1)
    assert.is_nil(c:getVertex(1))
    assert.is_nil(c:getEdge(1))
    assert.equals(0, c:getVertexCount())
    local list, n = c:getVertices({ 1, 2, 3 })
    assert.same({}, list)
    assert.equals(0, n)
  end)

  it('grows everywhere when scaled', function()
    local c = S.hapes.Circle(0, 0, 5):scale(2)
    assert.equals(10, c:getRadius())
    nearList(bbox(c), { -10, -10, 20, 20 })
    nearList({ c:project(1, 0) }, { -10, 10 })
    assert.is_true(c:containsPoint(9, 0))
    near(c:getArea(), 100 * pi)
    nearList({ c:unpack() }, { 0, 0, 10, 0 })
  end)

  it('validates its arguments', function()
    raisesAt(function() S.hapes.Circle(0, 0) end, 'strike.Circle: radius must be a finite number > 0, got nil')
    raisesAt(function() S.hapes.Circle(0, 0, 0) end, 'radius must be a finite number > 0, got 0')
    raisesAt(function() S.hapes.Circle(0, 0, 1e200) end, 'strike.Circle: radius too large')
  end)
end)

describe('shape transforms', function()
  it('return self', function()
    local r = S.hapes.Rectangle(0, 0, 2)
    assert.equals(r, r:translate(1, 1))
    assert.equals(r, r:translateTo(0, 0))
    assert.equals(r, r:rotate(1))
    assert.equals(r, r:rotateTo(0))
    assert.equals(r, r:scale(2))
  end)

  it('translate and translateTo move the centroid', function()
    local r = S.hapes.Rectangle(0, 0, 2):translate(3, 4)
    nearList({ r:getCentroid() }, { 3, 4 })
    r:translateTo(-1, -2)
    nearList({ r:getCentroid() }, { -1, -2 })
    nearList(bbox(r), { -2, -3, 2, 2 })
  end)

  it('rotate turns +x toward +y, about the centroid or a reference point', function()
    local e = S.hapes.Edge(0, 0, 10, 0):rotate(pi / 2)
    nearList({ e:getVertex(1) }, { 5, -5 })
    local r = S.hapes.Rectangle(10, 0, 2):rotate(pi / 2, 0, 0)
    nearList({ r:getCentroid() }, { 0, 10 })
  end)

  it('rotateTo sets the absolute angle, also about a reference point', function()
    local r = S.hapes.Rectangle(10, 0, 2)
    r:rotate(pi / 2, 0, 0)
    r:rotateTo(pi / 2, 0, 0) -- already there: nothing moves
    nearList({ r:getCentroid() }, { 0, 10 })
    r:rotateTo(0, 0, 0)
    nearList({ r:getCentroid() }, { 10, 0 })
    near(r:getAngle(), 0)
  end)

  it('scale defaults to the centroid and composes', function()
    local r = S.hapes.Rectangle(5, 5, 2)
    r:scale(2):scale(3)
    nearList(bbox(r), { -1, -1, 12, 12 })
    assert.equals(144, r:getArea())
    assert.equals(6, r:getScale())
    local q = S.hapes.Rectangle(10, 0, 2)
    q:scale(2, 0, 0):scale(2, 0, 0)
    nearList({ q:getCentroid() }, { 40, 0 })
    near(q:getRadius(), 4 * math.sqrt(2))
  end)

  it('validate their arguments', function()
    local r = S.hapes.Rectangle(0, 0, 2)
    raisesAt(function() r:translate(1) end, 'strike.Shape:translate: dy must be a finite number, got nil')
    raisesAt(function() r:translateTo(0 / 0, 1) end, 'strike.Shape:translateTo: x must be a finite number, got nan')
    raisesAt(function() r:rotate('a') end, 'strike.Shape:rotate: angle must be a finite number, got string')
    raisesAt(function() r:rotate(1, 0) end, 'strike.Shape:rotate: reference y must be a finite number, got nil')
    raisesAt(function() r:rotateTo() end, 'strike.Shape:rotateTo: angle must be a finite number, got nil')
    raisesAt(function() r:scale(0) end, 'strike.Shape:scale: factor must be a finite number > 0, got 0')
    raisesAt(function() r:scale(-1) end, 'got -1')
    nearList(bbox(r), { -1, -1, 2, 2 }) -- the failed calls changed nothing
  end)
end)

describe('shape getters', function()
  it('getVertex and getEdge return nil out of range, never an error', function()
    local r = S.hapes.Rectangle(0, 0, 2)
    for _, i in ipairs({ 0, -1, 5, 1.5, 'x' }) do
      assert.is_nil(r:getVertex(i))
      assert.is_nil(r:getEdge(i))
      assert.is_nil(r:getNormal(i))
    end
    assert.is_nil(r:getVertex())
  end)

  it('return transformed coordinates, refreshed after each transform', function()
    local r = S.hapes.Rectangle(0, 0, 2)
    nearList({ r:getVertex(1) }, { -1, -1 })
    r:translate(10, 0)
    nearList({ r:getVertex(1) }, { 9, -1 })
    r:rotate(pi)
    nearList({ r:getVertex(1) }, { 11, 1 })
  end)

  it('getVertices fills an out table and clears what is left in it', function()
    local out = { 9, 9, 9, 9, 9, 9, 9, 9, 9, 9 }
    local list, n = S.hapes.ConvexPolygon(0, 0, 1, 0, 0, 1):getVertices(out)
    assert.equals(out, list)
    assert.equals(3, n)
    assert.same({ 0, 0, 1, 0, 0, 1 }, list)
  end)

  it('project gives min and max along a unit vector', function()
    local r = S.hapes.Rectangle(0, 0, 2, 4)
    nearList({ r:project(1, 0) }, { -1, 1 })
    nearList({ r:project(0, 1) }, { -2, 2 })
    local s = math.sqrt(0.5)
    nearList({ r:project(s, s) }, { -3 * s, 3 * s })
    raisesAt(function() r:project(1) end, 'strike.Shape:project: ny must be a finite number, got nil')
  end)

  it('getRadius is the circumradius about the centroid', function()
    near(S.hapes.Rectangle(0, 0, 6, 8):getRadius(), 5)
    near(S.hapes.RegularPolygon(3, 3, 7, 4):getRadius(), 4)
  end)

  it('containsPoint is strict and takes x, y or a table', function()
    local r = S.hapes.Rectangle(0, 0, 10)
    assert.is_true(r:containsPoint(0, 0))
    assert.is_true(r:containsPoint({ x = 4, y = -4 }))
    assert.is_false(r:containsPoint(5, 0)) -- on the boundary
    assert.is_false(r:containsPoint(-10, 0))
    local c = S.hapes.Circle(0, 0, 5)
    assert.is_true(c:containsPoint(3, 3))
    assert.is_false(c:containsPoint(5, 0))
    raisesAt(function() r:containsPoint(1) end, 'strike.Shape:containsPoint: point y must be a finite number, got nil')
  end)

  it('ipairs and vecs iterate over the edges', function()
    local t = S.hapes.ConvexPolygon(0, 0, 4, 0, 0, 3)
    local seen = {}
    for i, x1, y1, x2, y2 in t:ipairs() do seen[#seen + 1] = { i, x1, y1, x2, y2 } end
    assert.same({ { 1, 0, 0, 4, 0 }, { 2, 4, 0, 0, 3 }, { 3, 0, 3, 0, 0 } }, seen)
    local vs = {}
    for i, dx, dy in t:vecs() do vs[#vs + 1] = { i, dx, dy } end
    assert.same({ { 1, 4, 0 }, { 2, -4, 3 }, { 3, 0, -3 } }, vs)
  end)

  it('a circle has one pseudo-edge facing the other shape', function()
    local c = S.hapes.Circle(0, 0, 2)
    local other = S.hapes.Circle(10, 0, 2)
    local count = 0
    for i, x1, y1, x2, y2 in c:ipairs(other) do
      count = count + 1
      assert.equals(1, i)
      nearList({ x1, y1, x2, y2 }, { 2, -2, 2, 2 })
    end
    assert.equals(1, count)
    for _, dx, dy in c:vecs(other) do nearList({ dx, dy }, { 0, 1 }) end
  end)
end)

describe('unpack and copy', function()
  it('unpack gives arguments that rebuild each shape as it is now', function()
    local shapes = {
      S.hapes.Rectangle(1, 2, 3, 4, 0.5),
      S.hapes.RegularPolygon(1, 2, 5, 3, 0.25),
      S.hapes.Ellipse(1, 2, 6, 3, 10, 0.3),
      S.hapes.Circle(1, 2, 3),
      S.hapes.Edge(1, 2, 5, 7),
      S.hapes.ConvexPolygon(0, 0, 4, 1, 2, 5),
    }
    for _, s in ipairs(shapes) do
      s:rotate(0.7):scale(1.5):translate(3, -2)
      local class = getmetatable(s)
      local rebuilt = class(s:unpack())
      nearList(verts(rebuilt), verts(s), 1e-9)
      nearList(bbox(rebuilt), bbox(s), 1e-9)
      near(rebuilt:getArea(), s:getArea(), 1e-9)
    end
  end)

  it('copy is independent, of the same class, and can move and turn', function()
    local r = S.hapes.Rectangle(0, 0, 4, 2):rotate(0.3)
    local c = r:copy()
    assert.equals(getmetatable(r), getmetatable(c))
    nearList(verts(c), verts(r))
    c:translate(10, 0)
    nearList({ r:getCentroid() }, { 0, 0 })
    local d = r:copy(5, 6, pi / 2)
    nearList({ d:getCentroid() }, { 5, 6 })
    near(d:getAngle(), pi / 2)
    nearList(bbox(d), { 4, 4, 2, 4 })
  end)

  it('a copy of a collider member has no parent', function()
    local r = S.hapes.Rectangle(0, 0, 1)
    S.trikers.Collider(r)
    assert.is_nil(r:copy():getParent())
  end)
end)

describe('more shape queries', function()
  it('getSupport gives the farthest vertex index, or the farthest point of a circle', function()
    local r = S.hapes.Rectangle(0, 0, 4, 2)
    assert.equals(3, r:getSupport(1, 1))
    assert.equals(1, r:getSupport(-1, -1))
    nearList({ S.hapes.Circle(1, 1, 2):getSupport(0, 1) }, { 1, 3 })
  end)

  it('getBounds gives min and max corners', function()
    nearList({ S.hapes.Rectangle(0, 0, 4, 2):getBounds() }, { -2, -1, 2, 1 })
    nearList({ S.hapes.Circle(1, 1, 2):getBounds() }, { -1, -1, 3, 3 })
  end)

  it('getRoot gives the outermost collider, or the shape itself', function()
    local s = S.hapes.Circle(0, 0, 1)
    assert.equals(s, s:getRoot())
    local outer = S.trikers.Collider(S.trikers.Collider(s))
    assert.equals(outer, s:getRoot())
    assert.equals(outer, outer:getRoot())
  end)

  it('getAngle and getScale accumulate', function()
    local c = S.hapes.Circle(0, 0, 1, 0.5):rotate(0.25):scale(3):scale(0.5)
    near(c:getAngle(), 0.75)
    near(c:getScale(), 1.5)
  end)

  it('constructors reject every bad argument', function()
    raisesAt(function() S.hapes.Circle(0, 0, 1, 0 / 0) end, 'strike.Circle: angle must be a finite number, got nan')
    raisesAt(function() S.hapes.Circle('0', 0, 1) end, 'strike.Circle: x must be a finite number, got string "0"')
    raisesAt(function() S.hapes.Edge(0, 0, 1e300, 1e300) end, 'strike.Edge: too large: its length is 1.414')
    raisesAt(function() S.hapes.RegularPolygon(0, nil, 3, 1) end,
      'strike.RegularPolygon: y must be a finite number, got nil')
    raisesAt(function() S.hapes.RegularPolygon(0, 0, 3, 1, {}) end, 'angle must be a finite number, got table')
    raisesAt(function() S.hapes.Ellipse(0, 0, -1, 1) end,
      'strike.Ellipse: semi-axis a must be a finite number > 0, got -1')
    raisesAt(function() S.hapes.Ellipse(0, 0, 1, 1, 8, -math.huge) end, 'angle must be a finite number, got -inf')
    raisesAt(function() S.hapes.Rectangle(0, 0, 1, nil, true) end, 'angle must be a finite number, got true')
  end)
end)

describe('huge and degenerate transforms', function()
  it('refuse to overflow and leave the shape as it was', function()
    local r = S.hapes.Rectangle(0, 0, 2)
    raisesAt(function() r:translate(1e308, 0):translate(1e308, 0) end,
      'strike.Shape:translate: the result would overflow (coordinates too large)')
    nearList({ r:getCentroid() }, { 1e308, 0 }, 1e300)
    r:translateTo(0, 0)
    raisesAt(function() r:scale(1e200):scale(1e200) end, 'strike.Shape:scale: the result would be too large')
    raisesAt(function() r:translateTo(0, 0):rotate(math.pi, 1e308, 0) end,
      'strike.Shape:rotate: the result would overflow')
    raisesAt(function() r:scale(1e-200):scale(1e-200):scale(1e-200) end,
      'strike.Shape:scale: the result would be too small')
    assert.is_true(r:getScale() > 0)
    local p = S.hapes.Point(0, 0)
    raisesAt(function() p:scale(1e-200):scale(1e-200):scale(1e-200) end,
      'strike.Shape:scale: the scale would underflow to 0')
    assert.is_true(p:getScale() > 0)
  end)

  it('refuse to overflow a collider and move none of its shapes', function()
    local c = S.trikers.Collider(S.hapes.Rectangle(0, 0, 2), S.hapes.Circle(1e308, 0, 1))
    raisesAt(function() c:translate(1e308, 0) end, 'strike.Collider:translate: the result would overflow')
    nearList({ (c:unpack()):getCentroid() }, { 0, 0 })
    raisesAt(function() c:scale(10, 0, 0) end, 'strike.Collider:scale: the result would overflow')
    raisesAt(function() c:rotate(1, -1e308, 0) end, 'strike.Collider:rotate: the result would overflow')
    nearList({ (c:unpack()):getCentroid() }, { 0, 0 })
  end)
end)

describe('ConvexPolygon:merge', function()
  it('returns the union when it is convex, else false', function()
    local a, b = S.hapes.Rectangle(0, 0, 2), S.hapes.Rectangle(2, 0, 2)
    local m = a:merge(b)
    assert.equals(S.hapes.ConvexPolygon, getmetatable(m))
    assert.equals(8, m:getArea())
    nearList({ m:getBbox() }, { -1, -1, 4, 2 })
    assert.is_false(a:merge(S.hapes.Rectangle(1, 0, 2)))   -- overlapping
    assert.is_false(a:merge(S.hapes.Rectangle(2, 1, 2)))   -- an L step
    assert.is_false(a:merge(S.hapes.Circle(2, 0, 1)))
    assert.is_false(a:merge(S.hapes.Edge(1, -1, 1, 1)))
    assert.is_false(a:merge(nil))
  end)
end)
