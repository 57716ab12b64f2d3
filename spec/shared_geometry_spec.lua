-- Shapes share their local geometry (`_l`, strike/base/VertexShape.lua): a shape built with
-- the very numbers of one of the last few built takes that one's table. Sharing must be
-- invisible: the same numbers to the bit (the sign of a zero too), nothing that changes a
-- shape's local geometry in place may reach another shape's, and no answer may differ.
local S = require('strike')
local VertexShape = require('strike.base.VertexShape')

local H, T = S.hapes, S.trikers

-- Every number of a shape's local geometry, as text that tells -0.0 from 0.0.
local function numbers(s)
  local out = {}
  for k = 1, #s._l do
    local v = s._l[k]
    out[k] = v == 0 and (1 / v < 0 and '-0' or '0') or ('%.17g'):format(v)
  end
  return table.concat(out, ' ')
end

describe('shared local geometry', function()
  it('shapes of the same kind and size share one table; another size has its own', function()
    local a, b = H.Rectangle(0, 0, 2, 2), H.Rectangle(30, -7, 2, 2)
    local c = T.Rectangle(9, 9, 2, 2):unpack()
    assert.equals(a._l, b._l)
    assert.equals(a._l, c._l)
    assert.are_not.equals(a._l, H.Rectangle(0, 0, 2, 3)._l)
    -- (where the rounding of the centroid is the same: a wave spawned at one place)
    local p, q = H.RegularPolygon(100, 200, 6, 5), H.RegularPolygon(100, 200, 6, 5, 0.5)
    assert.equals(p._l, q._l)
    local e1, e2 = H.Edge(0, 0, 10, 0), H.Edge(5, 5, 15, 5)
    assert.equals(e1._l, e2._l)
  end)

  it('a table is shared only when every number is the same to the bit', function()
    local share = VertexShape._shareGeometry
    local l = { 1.5, -2.5, 0.0, -1.0, 1.5, 2.5, 1.0, 0.0 }
    local g = share(l, 2)
    assert.are_not.equals(l, g) -- (the argument is never kept: callers pass scratch tables)
    assert.equals(g, share({ 1.5, -2.5, 0.0, -1.0, 1.5, 2.5, 1.0, 0.0 }, 2))
    -- one ulp apart, in the last number, is another geometry
    local ulp = { 1.5, -2.5, 0.0, -1.0, 1.5, 2.5, 1.0, 2 ^ -1074 }
    assert.are_not.equals(g, share(ulp, 2))
    -- -0.0 is not 0.0: a zero's sign shows in the results (a normal's component, 1 / x)
    -- (made at run time: Lua 5.1 keeps one constant for 0.0 and -0.0 in a function)
    local zero = 0.0
    local negative = { 1.5, -2.5, -zero, -1.0, 1.5, 2.5, 1.0, 0.0 }
    local h = share(negative, 2)
    assert.are_not.equals(g, h)
    assert.equals(-math.huge, 1 / h[3])
    assert.equals(math.huge, 1 / g[3])
    -- the same first numbers but more of them is another geometry, and so is fewer
    local three = share({ 1.5, -2.5, 0.0, -1.0, 1.5, 2.5, 1.0, 0.0, 0, 1, 0, 1 }, 3)
    assert.are_not.equals(g, three)
    assert.equals(12, #three)
    assert.equals(8, #share({ 1.5, -2.5, 0.0, -1.0, 1.5, 2.5, 1.0, 0.0 }, 2))
  end)

  it('a shared shape gives the numbers and answers an own table would', function()
    -- (a rectangle built alone, with no earlier one of its numbers, against one built after
    -- many of them: the same numbers, the same vertices and the same collision)
    local alone = H.Rectangle(1e6 + 0.3, -2e5 + 0.7, 16, 12)
    local many = {}
    for i = 1, 50 do many[i] = H.Rectangle(1e6 + 0.3, -2e5 + 0.7, 16, 12) end
    local last = many[50]
    assert.equals(numbers(alone), numbers(last))
    assert.same({ alone:getVertices() }, { last:getVertices() })
    local other = H.RegularPolygon(1e6 + 9, -2e5 + 4, 7, 6, 0.4)
    local m1, m2 = S.AT(alone, other), S.AT(last, other)
    assert.is_not_nil(m1)
    assert.same({ m1.x, m1.y, m1.edgeIndex }, { m2.x, m2.y, m2.edgeIndex })
  end)

  it('a space\'s queryRect changes no game shape\'s local geometry (its probe has its own)', function()
    -- (the probe is a 1 by 1 rectangle at the origin whose corners each queryRect sets in
    -- place; a game's rectangle of the same numbers shares them until the probe takes a copy)
    local game = H.Rectangle(0, 0, 1, 1)
    local before = numbers(game)
    local space = S.pace()
    local wall = space:add(T.Rectangle(100, 100, 10, 10))
    local list, n = space:queryRect(95, 95, 40, 30)
    assert.equals(1, n)
    assert.equals(wall, list[1])
    assert.equals(before, numbers(game))
    local x0, y0, x1, y1 = game:getBounds()
    assert.same({ -0.5, -0.5, 0.5, 0.5 }, { x0, y0, x1, y1 })
    assert.same({ 0, 0, 1, 1, 0 }, { game:unpack() })
    -- and a 1 by 1 rectangle built after the query still gets the numbers of its size
    assert.equals(before, numbers(H.Rectangle(0, 0, 1, 1)))
  end)

  it('a disc capsule gets its own normals without changing another shape\'s geometry', function()
    local d1 = H.Capsule(0, 0, 4, 4)
    local d2 = H.Capsule(10, 10, 4, 4)
    assert.equals(d1._l, d2._l)
    for _, d in ipairs({ d1, d2 }) do
      assert.same({ 1, 0 }, { d:getNormal(1) })
      assert.same({ -1, 0 }, { d:getNormal(2) })
    end
    local pill = H.Capsule(0, 0, 4, 10)
    assert.same({ 1, 0 }, { pill:getNormal(1) })
    assert.same({ -1, 0 }, { pill:getNormal(2) })
    assert.same({ 0, -3, 0, 3 }, { pill:getVertex(1), select(2, pill:getVertex(1)), pill:getVertex(2),
      select(2, pill:getVertex(2)) })
  end)

  it('every vertex and normal of a shape\'s local geometry is a float (integers would compare equal)', function()
    local mathType = math.type -- luacheck: ignore 143 (Lua 5.3+)
    if not mathType then return end
    local shapes = { H.Rectangle(0, 0, 2, 2), H.Rectangle(3, 4, 10, 6, 0.5, 2), H.RegularPolygon(1, 1, 5, 3),
      H.ConvexPolygon(0, 0, 4, 0, 4, 4), H.Edge(0, 0, 4, 0), H.Capsule(0, 0, 2, 2), H.Capsule(0, 0, 2, 8),
      H.Ellipse(0, 0, 4, 2) }
    for i, s in ipairs(shapes) do
      for k = 1, 4 * s:getVertexCount() do
        assert.equals('float', mathType(s._l[k]), ('shape %d, number %d'):format(i, k))
      end
    end
  end)

  it('a class\'s sizes are part of its local geometry: unpack gives each shape its own', function()
    -- (far from the origin, where 2 and 2.01 wide rectangles have the same corners once rounded)
    local x = 1e15
    local a, b = H.Rectangle(x, 0, 2, 2), H.Rectangle(x, 0, 2.01, 2)
    assert.equals(numbers(a):match('^(.*) [^ ]+ [^ ]+$'), numbers(b):match('^(.*) [^ ]+ [^ ]+$'))
    assert.are_not.equals(a._l, b._l)
    assert.same({ x, 0, 2, 2, 0 }, { a:unpack() })
    assert.same({ x, 0, 2.01, 2, 0 }, { b:unpack() })
    assert.same({ 0, 0, 6, 5, 0 }, { H.RegularPolygon(0, 0, 6, 5):unpack() })
    assert.same({ 0, 0, 6, 5.5, 0 }, { H.RegularPolygon(0, 0, 6, 5.5):unpack() })
    assert.same({ 0, 0, 4, 2, 8, 0 }, { H.Ellipse(0, 0, 4, 2):unpack() })
    assert.same({ 0, 0, 4, 2, 12, 0 }, { H.Ellipse(0, 0, 4, 2, 12):unpack() })
    -- and their integers stay integers, their floats floats (Lua 5.3+ tells them apart)
    local mathType = math.type -- luacheck: ignore 143 (Lua 5.3+)
    if mathType then
      local int, float = H.Rectangle(0, 0, 2, 2), H.Rectangle(0, 0, 2.0, 2.0)
      assert.are_not.equals(int._l, float._l)
      assert.same({ 'integer', 'integer' }, { mathType(select(3, int:unpack())), mathType(select(4, int:unpack())) })
      assert.same({ 'float', 'float' }, { mathType(select(3, float:unpack())), mathType(select(4, float:unpack())) })
      assert.equals('float', mathType(select(3, H.RegularPolygon(0, 0, 6.0, 5):unpack())))
      assert.equals('integer', mathType(select(3, H.RegularPolygon(0, 0, 6, 5):unpack())))
    end
  end)

  it('a rectangle the general path builds (no fast path) keeps its sizes too, and so does a rounded one', function()
    -- (outside ConvexPolygon._safeConvex: 1e-7 wide at 1e3 from the origin; and a rounded one)
    assert.same({ 1000, 0, 1e-7, 1, 0 }, { H.Rectangle(1000, 0, 1e-7, 1):unpack() })
    assert.same({ 0, 0, 10, 6, 0, 2 }, { H.Rectangle(0, 0, 10, 6, 0, 2):unpack() })
    local ok = pcall(H.Rectangle, 0, 0, 1e200, 1) -- (an error there leaves no sizes for the next shape)
    assert.is_false(ok)
    local p = H.ConvexPolygon(0, 0, 4, 0, 4, 4)
    assert.equals(12, #p._l)
  end)
end)
