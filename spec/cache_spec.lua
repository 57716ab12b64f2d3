-- World-space data is recomputed once per change, on the next query, never per getter.
local S = require('strike')

-- Count how often `shape` recomputes its world-space cache.
local function counted(shape)
  local n = 0
  local refresh = shape._refresh
  shape._refresh = function(self) n = n + 1 return refresh(self) end
  return function() return n end
end

describe('world-space caches', function()
  it('transforms only mark a shape dirty; the next query recomputes once', function()
    local r = S.hapes.RegularPolygon(0, 0, 8, 10)
    local count = counted(r)
    r:getBbox()
    assert.equals(1, count())
    r:translate(1, 2):rotate(0.3):scale(2):translateTo(5, 5):rotateTo(1)
    assert.equals(1, count()) -- five transforms, no work yet
    for i = 1, 8 do r:getVertex(i) end
    r:getBbox()
    r:getEdge(3)
    r:getVertices()
    r:project(1, 0)
    S.AT(r, S.hapes.Circle(0, 0, 1))
    assert.equals(2, count()) -- every query after them shares one refresh
  end)

  it('moving a collider refreshes each of its shapes once, at the next query', function()
    local a, b = S.hapes.Rectangle(0, 0, 10), S.hapes.Circle(20, 0, 5)
    local c = S.trikers.Collider(a, b)
    c:getBbox()
    local ca, cb = counted(a), counted(b)
    for _ = 1, 10 do c:translate(1, 0):rotate(0.1) end
    assert.equals(0, ca())
    assert.equals(0, cb())
    c:getBbox()
    c:getRadius()
    S.triking(c, S.trikers.Circle(100, 0, 1))
    assert.equals(1, ca())
    assert.equals(1, cb())
  end)

  it('a circle is refreshed lazily too', function()
    local c = S.hapes.Circle(0, 0, 3)
    local count = counted(c)
    c:translate(1, 1):scale(2)
    c:getBbox()
    c:getBounds()
    assert.equals(1, count())
  end)
end)

-- Nested colliders: a change deep in the tree must reach every enclosing collider's caches
-- (Shape:_touch and Collider's invalidate walk up the parent chain; see the cache protocol
-- at the top of strike/colliders/Collider.lua). Every mutation is crossed with every query
-- on the outer collider and on the outermost one. The expected answer comes from a fresh,
-- flat collider of copies of the leaves the tree holds now (found through unpack, so no
-- cache is read; nothing nested, so its answer does not rest on the protocol under test),
-- never from the object under test. Each pair also checks that the mutation does (or,
-- listed in `same`, does not) change that expected answer: the probe body and the ray are
-- placed where the change shows (hit only after it, or only before it).
describe('nested collider caches', function()
  local H, T = S.hapes, S.trikers
  local pi = math.pi
  local unpack = table.unpack or unpack -- luacheck: ignore 113 143

  -- The leaves under `node`, depth first, read from the children lists (no cache).
  local function leafList(node, out)
    out = out or {}
    if node.type == 'collider' then
      for _, child in ipairs({ node:unpack() }) do leafList(child, out) end
    else
      out[#out + 1] = node
    end
    return out
  end

  -- A new collider of copies of the leaves, in the same order: every cache empty.
  local function fresh(node)
    local copies = {}
    for i, leaf in ipairs(leafList(node)) do copies[i] = leaf:copy() end
    return T.Collider(unpack(copies))
  end

  -- Where `leaf` is among the leaves that `tree` holds now.
  local function indexIn(tree, leaf)
    for i, l in ipairs(leafList(tree)) do
      if l == leaf then return i end
    end
    return 'a shape no longer in the tree'
  end

  -- Each query returns its answer as a flat list (shapes as their index in the tree).
  local queries = {
    { 'getShapeCount', function(c) return { c:getShapeCount() } end },
    { 'elems', function(c)
      local r = {}
      for leaf in c:elems() do
        local x, y = leaf:getCentroid()
        for _, v in ipairs({ indexIn(c, leaf), leaf.name, x, y, leaf:getAngle(), leaf:getScale() }) do
          r[#r + 1] = v
        end
      end
      return r
    end },
    { 'getBbox', function(c) return { c:getBbox() } end },
    { 'getBounds', function(c) return { c:getBounds() } end },
    { 'getRadius', function(c) return { c:getRadius() } end },
    { 'getArea', function(c) return { c:getArea() } end },
    { 'getCentroid', function(c) return { c:getCentroid() } end },
    { 'getAreaCentroid', function(c) return { c:getAreaCentroid() } end },
    { 'S.triking', function(c, probe)
      local m = S.triking(c, probe)
      if not m then return { 'no collision' } end
      return { m.x, m.y, m.depth, indexIn(c, m.colliderShape) }
    end },
    { 'rayCast', function(c, _, ray)
      local d, x, y, nx, ny, leaf = c:rayCast(unpack(ray))
      if not d then return { 'miss' } end
      return { d, x, y, nx, ny, indexIn(c, leaf) }
    end },
    { 'rayIntersects', function(c, _, ray) return { c:rayIntersects(unpack(ray)) } end },
  }

  -- Each fixture: build() returns the tree's parts by name; the mutations: name,
  -- apply(tree), probe() a new body the tree hits only before or only after the mutation,
  -- ray {x, y, dx, dy} likewise (or, for consolidate, stopped at another leaf), and `same`,
  -- the queries whose answer the mutation does not change.
  local fixtures = {
    {
      name = 'many leaves',
      -- outermost ⊃ { outer ⊃ { inner ⊃ { A, B, s, c }, m }, r }. A and B share the edge
      -- x = 5 (consolidate merges them); s is the leaf the leaf mutations change.
      --   A [-5, 5] x [-5, 5]     B [5, 15] x [-5, 5]     s [35, 45] x [-1, 1]
      --   c circle (10, 20) r 3   m circle (-20, -30) r 5   r triangle x [-30, -20], y [10, 18]
      build = function()
        local t = {}
        t.A, t.B = H.Rectangle(0, 0, 10, 10), H.Rectangle(10, 0, 10, 10)
        t.s = H.Rectangle(40, 0, 10, 2)
        t.inner = T.Collider(t.A, t.B, t.s, H.Circle(10, 20, 3))
        t.outer = T.Collider(t.inner, H.Circle(-20, -30, 5))
        t.outermost = T.Collider(t.outer, H.ConvexPolygon(-30, 10, -20, 10, -25, 18))
        return t
      end,
      mutations = {
        { name = 's:translate(10, 6)', apply = function(t) t.s:translate(10, 6) end,
          probe = function() return H.Circle(50, 6, 1) end, ray = { 50, 60, 0, -1 },
          same = { 'getShapeCount', 'getArea' } },
        { name = 's:translateTo(50, -15)', apply = function(t) t.s:translateTo(50, -15) end,
          probe = function() return H.Circle(50, -15, 1) end, ray = { 80, -15, -1, 0 },
          same = { 'getShapeCount', 'getArea' } },
        { name = 's:rotate(pi / 2)', apply = function(t) t.s:rotate(pi / 2) end,
          probe = function() return H.Circle(40, 4, 0.5) end, ray = { 30, 4, 1, 0 },
          same = { 'getShapeCount', 'getArea', 'getCentroid', 'getAreaCentroid' } },
        { name = 's:rotateTo(pi / 2, 45, 0)', apply = function(t) t.s:rotateTo(pi / 2, 45, 0) end,
          probe = function() return H.Circle(45, -8, 0.5) end, ray = { 60, -8, -1, 0 },
          same = { 'getShapeCount', 'getArea' } },
        { name = 's:scale(2)', apply = function(t) t.s:scale(2) end,
          probe = function() return H.Circle(48, 0, 0.5) end, ray = { 48, 30, 0, -1 },
          same = { 'getShapeCount' } },
        { name = 'inner:translate(0, 50)', apply = function(t) t.inner:translate(0, 50) end,
          probe = function() return H.Circle(0, 50, 1) end, ray = { -20, 50, 1, 0 },
          same = { 'getShapeCount', 'getArea' } },
        { name = 'inner:rotate(pi / 2, 0, 0)', apply = function(t) t.inner:rotate(pi / 2, 0, 0) end,
          probe = function() return H.Circle(0, 40, 1) end, ray = { -10, 38, 1, 0 },
          same = { 'getShapeCount', 'getArea' } },
        { name = 'inner:scale(2, 0, 0)', apply = function(t) t.inner:scale(2, 0, 0) end,
          probe = function() return H.Circle(80, 0, 1) end, ray = { 80, 30, 0, -1 },
          same = { 'getShapeCount' } },
        { name = 'inner:add(a new shape)', apply = function(t) t.inner:add(H.Rectangle(60, 0, 4, 4)) end,
          probe = function() return H.Circle(60, 0, 1) end, ray = { 60, 30, 0, -1 },
          same = {} },
        { name = 'inner:remove(3) (s)', apply = function(t) t.inner:remove(3) end,
          probe = function() return H.Circle(40, 0, 0.5) end, ray = { 40, 30, 0, -1 },
          same = {} },
        -- The ray starts inside A: it leaves A at x = 5 but A + B at x = 15. The union is
        -- the same, so whether the ray hits at all is too, and so is S.triking's answer (the
        -- outline rule answers for the union of the members however they are cut).
        { name = 'inner:consolidate()', apply = function(t) t.inner:consolidate() end,
          probe = function() return H.Rectangle(5, 4.5, 2, 5) end, ray = { -2, 1, 1, 0 },
          same = { 'getBbox', 'getBounds', 'getRadius', 'getArea', 'getCentroid', 'getAreaCentroid',
            'rayIntersects', 'S.triking' } },
        -- (a stale leaf list would still hold A and B where they were)
        { name = 'inner:consolidate() then the merged piece translate(0, 60)', apply = function(t)
          t.inner:consolidate()
          local merged = t.inner:unpack()
          merged:translate(0, 60)
        end,
          probe = function() return H.Circle(5, 60, 1) end, ray = { -20, 60, 1, 0 },
          same = { 'getArea' } },
        -- Two changes with a query of the inner collider alone in between: the inner one
        -- has its area again but not its bounds when the second change walks up.
        { name = 's:translate(10, 6), inner:getArea(), s:scale(2)', apply = function(t)
          t.s:translate(10, 6)
          t.inner:getArea()
          t.s:scale(2)
        end,
          probe = function() return H.Circle(58, 6, 1) end, ray = { 58, 30, 0, -1 },
          same = { 'getShapeCount' } },
        -- A collider's translation shifts the caches of it and of the colliders in it (see
        -- Collider's translateBy): the next change below must still reach every one of them.
        { name = 'outer:translate(0, 50) then s:translate(10, 6)', apply = function(t)
          t.outer:translate(0, 50)
          t.s:translate(10, 6)
        end,
          probe = function() return H.Circle(50, 56, 1) end, ray = { 50, 90, 0, -1 },
          same = { 'getShapeCount', 'getArea' } },
        { name = 'outer:translateTo(0, 0), inner:getBbox(), s:scale(2)', apply = function(t)
          t.outer:translateTo(0, 0)
          t.inner:getBbox()
          t.s:scale(2)
        end,
          probe = function() return H.Circle(5, 0, 1) end, ray = { -60, 0, 1, 0 },
          same = { 'getShapeCount' } },
        { name = 'inner:translate(0, 50) then inner:add(a new shape)', apply = function(t)
          t.inner:translate(0, 50)
          t.inner:add(H.Rectangle(60, 0, 4, 4))
        end,
          probe = function() return H.Circle(60, 0, 1) end, ray = { 60, 30, 0, -1 },
          same = {} },
        -- A move (bounds stale all the way up, leaf lists still good), then a new shape.
        { name = 's:translate(10, 6) then inner:add(a new shape)', apply = function(t)
          t.s:translate(10, 6)
          t.inner:add(H.Rectangle(60, 0, 4, 4))
        end,
          probe = function() return H.Circle(60, 0, 1) end, ray = { 60, 30, 0, -1 },
          same = {} },
      },
    },
    {
      -- One leaf at every level: S.triking takes its one-leaf path (a collider's `_single`).
      name = 'one leaf',
      build = function()
        local t = {}
        t.s = H.Rectangle(5, 5, 4, 4) -- [3, 7] x [3, 7]
        t.inner = T.Collider(t.s)
        t.outer = T.Collider(t.inner)
        t.outermost = T.Collider(t.outer)
        return t
      end,
      mutations = {
        { name = 's:translate(20, 0)', apply = function(t) t.s:translate(20, 0) end,
          probe = function() return H.Circle(25, 5, 1) end, ray = { 25, 30, 0, -1 },
          same = { 'getShapeCount', 'getArea', 'getRadius' } },
        -- (a diamond now, its corner at (5, 7.83))
        { name = 's:rotate(pi / 4)', apply = function(t) t.s:rotate(pi / 4) end,
          probe = function() return H.Circle(5, 7.5, 0.4) end, ray = { 0, 7.5, 1, 0 },
          same = { 'getShapeCount', 'getArea', 'getCentroid', 'getAreaCentroid', 'getRadius' } },
        { name = 'inner:scale(2, 0, 0)', apply = function(t) t.inner:scale(2, 0, 0) end,
          probe = function() return H.Circle(13, 13, 0.5) end, ray = { 13, 30, 0, -1 },
          same = { 'getShapeCount' } },
        { name = 'inner:add(a new shape)', apply = function(t) t.inner:add(H.Rectangle(20, 5, 4, 4)) end,
          probe = function() return H.Circle(20, 5, 1) end, ray = { 20, 30, 0, -1 },
          same = {} },
        { name = 'inner:remove(1)', apply = function(t) t.inner:remove(1) end,
          probe = function() return H.Circle(5, 5, 1) end, ray = { 5, 30, 0, -1 },
          same = {} },
        { name = 'inner:remove(1) then inner:add(a new shape)', apply = function(t)
          t.inner:remove(1)
          t.inner:add(H.Circle(30, 5, 2))
        end,
          probe = function() return H.Circle(30, 5, 1) end, ray = { 30, 30, 0, -1 },
          same = { 'getShapeCount' } },
      },
    },
  }

  local function sameAnswer(a, b)
    if #a ~= #b then return false end
    for i = 1, #b do
      local x, y = a[i], b[i]
      if type(x) == 'number' and type(y) == 'number' then
        if math.abs(x - y) > 1e-9 * (1 + math.abs(y)) or x ~= x then return false end
      elseif x ~= y then
        return false
      end
    end
    return true
  end

  local function show(a)
    local parts = {}
    for i, v in ipairs(a) do parts[i] = type(v) == 'number' and ('%.17g'):format(v) or tostring(v) end
    return '{ ' .. table.concat(parts, ', ') .. ' }'
  end

  for _, fixture in ipairs(fixtures) do
    describe(fixture.name, function()
      for _, m in ipairs(fixture.mutations) do
        local same = {}
        for _, name in ipairs(m.same) do same[name] = true end
        for _, observer in ipairs({ 'outer', 'outermost' }) do
          for _, q in ipairs(queries) do
            local qname, ask = q[1], q[2]
            it(('%s then %s:%s'):format(m.name, observer, qname), function()
              local t = fixture.build()
              local probe = m.probe()
              -- Fill every cache. (Querying the outermost collider alone would fill them
              -- all; going innermost first lets each nested collider refresh through its
              -- own queries, so a broken nested refresh shows after the mutation, not here.)
              for _, level in ipairs({ 'inner', 'outer', 'outermost' }) do
                for _, each in ipairs(queries) do each[2](t[level], probe, m.ray) end
              end
              local before = ask(fresh(t[observer]), probe, m.ray)
              m.apply(t)
              local want = ask(fresh(t[observer]), probe, m.ray)
              if same[qname] then
                assert(sameAnswer(want, before), ('the mutation should not change this answer: %s before, %s after')
                  :format(show(before), show(want)))
              else
                assert(not sameAnswer(want, before),
                  ('the mutation should change this answer, %s'):format(show(want)))
              end
              local got = ask(t[observer], probe, m.ray)
              assert(sameAnswer(got, want), ('expected %s, got %s'):format(show(want), show(got)))
            end)
          end
        end
      end
    end)
  end
end)

-- The same tree against numbers worked out by hand: an expectation that, unlike the fresh
-- collider above, owes nothing to strike's own aggregate code.
describe('nested collider caches, by hand', function()
  local H, T = S.hapes, S.trikers
  local near = require('spec.helpers.expect').near

  local function build()
    local s = H.Rectangle(40, 0, 10, 2)
    local inner = T.Collider(H.Rectangle(0, 0, 10, 10), H.Rectangle(10, 0, 10, 10), s, H.Circle(10, 20, 3))
    local outer = T.Collider(inner, H.Circle(-20, -30, 5))
    local outermost = T.Collider(outer, H.ConvexPolygon(-30, 10, -20, 10, -25, 18))
    for _, c in ipairs({ inner, outer, outermost }) do
      c:getShapeCount()
      c:getBounds()
      c:getRadius()
      c:getAreaCentroid()
    end
    return s, inner, outer, outermost
  end

  local function bounds(c, x0, y0, x1, y1)
    local a, b, c2, d = c:getBounds()
    near(a, x0, 1e-12, 'minx')
    near(b, y0, 1e-12, 'miny')
    near(c2, x1, 1e-12, 'maxx')
    near(d, y1, 1e-12, 'maxy')
  end

  -- Areas: A and B 100 each, s 20, c 9 pi, m 25 pi, r 40 (centroid (-25, 12 + 2/3)).
  local pi = math.pi
  local function centroid(c, parts)
    local a, ax, ay = 0, 0, 0
    for _, p in ipairs(parts) do a, ax, ay = a + p[1], ax + p[1] * p[2], ay + p[1] * p[3] end
    local x, y = c:getCentroid()
    near(x, ax / a, 1e-9, 'centroid x')
    near(y, ay / a, 1e-9, 'centroid y')
    near(c:getArea(), a, 1e-9, 'area')
  end
  local A, B, C, M, R = { 100, 0, 0 }, { 100, 10, 0 }, { 9 * pi, 10, 20 }, { 25 * pi, -20, -30 }, { 40, -25, 38 / 3 }

  it('before any change', function()
    local _, _, outer, outermost = build()
    assert.equals(5, outer:getShapeCount())
    assert.equals(6, outermost:getShapeCount())
    bounds(outer, -25, -35, 45, 23)
    bounds(outermost, -30, -35, 45, 23)
    centroid(outer, { A, B, { 20, 40, 0 }, C, M })
    centroid(outermost, { A, B, { 20, 40, 0 }, C, M, R })
  end)

  it('after the leaf moves and grows, two and three levels down', function()
    local s, _, outer, outermost = build()
    s:translate(10, 6):scale(2)
    bounds(outer, -25, -35, 60, 23)
    bounds(outermost, -30, -35, 60, 23)
    centroid(outer, { A, B, { 80, 50, 6 }, C, M })
    centroid(outermost, { A, B, { 80, 50, 6 }, C, M, R })
    assert.is_truthy(S.triking(outermost, H.Circle(58, 6, 1)))
    near(outer:rayCast(58, 30, 0, -1), 22, 1e-12)
  end)

  it('after the inner collider gains a shape and merges two', function()
    local _, inner, outer, outermost = build()
    inner:add(H.Rectangle(60, 0, 4, 4))
    inner:consolidate()
    assert.equals(5, outer:getShapeCount())
    assert.equals(6, outermost:getShapeCount())
    bounds(outermost, -30, -35, 62, 23)
    centroid(outermost, { A, B, { 20, 40, 0 }, C, M, R, { 16, 60, 0 } })
    near(outer:rayCast(-2, 1, 1, 0), 17, 1e-12) -- (it starts inside A + B: its exit)
    near(S.triking(outermost, H.Rectangle(5, 4.5, 2, 5)).depth, 3, 1e-12)
  end)

  -- elems' positions are made by its first use, then kept by every change of the leaves
  it('elems before and after members are added, removed and nested', function()
    local function leaves(c)
      local list = {}
      for shape in c:elems() do
        list[#list + 1] = shape
        assert.is_true(#list <= 10, 'elems does not end')
      end
      return list
    end
    local a, b, d = H.Circle(0, 0, 1), H.Circle(5, 0, 1), H.Circle(9, 0, 1)
    local inner = T.Collider(b)
    local c = T.Collider(a, inner)
    assert.same({ a, b }, leaves(c))
    c:add(d)
    assert.same({ a, b, d }, leaves(c))
    local e = H.Circle(0, 9, 1)
    inner:add(e)
    assert.same({ a, b, e, d }, leaves(c))
    c:remove(1)
    assert.same({ b, e, d }, leaves(c))
    assert.same({ b, e }, leaves(inner))
    -- a loop that removes the leaf it is at ends there (it used to start over, for ever)
    local seen = 0
    for shape in c:elems() do
      seen = seen + 1
      assert.is_true(seen <= 10, 'elems does not end')
      if shape == b then inner:remove(1) end
    end
    assert.equals(1, seen)
  end)

  -- A moved collider shifts the cached sums its centroid comes from (collider.lua: shift);
  -- an enclosing collider then rebuilds its own from them. Area, length and points each
  -- decide a centroid in turn, so each is checked with nothing of the ones before it.
  it('a nested collider of edges only, or of points only, moved, keeps the outer centroid right', function()
    -- edges: the length-weighted mean of the midpoints
    local inner = T.Collider(H.Edge(0, 0, 10, 0), H.Edge(0, 10, 0, 30)) -- lengths 10, 20
    local outer = T.Collider(inner, H.Edge(100, 0, 100, 10)) -- length 10, midpoint (100, 5)
    outer:getCentroid()
    inner:translate(3, 4) -- midpoints (8, 4) and (3, 24)
    local x, y = outer:getCentroid()
    assert.near((10 * 8 + 20 * 3 + 10 * 100) / 40, x, 1e-12)
    assert.near((10 * 4 + 20 * 24 + 10 * 5) / 40, y, 1e-12)
    inner:translateTo(0, 0) -- its centroid to the origin
    local ix, iy = inner:getCentroid()
    assert.near(0, ix, 1e-12)
    assert.near(0, iy, 1e-12)
    x, y = outer:getCentroid()
    assert.near((30 * 0 + 10 * 100) / 40, x, 1e-12)
    assert.near((30 * 0 + 10 * 5) / 40, y, 1e-12)
    -- points: the mean of the points
    local pin = T.Collider(H.Point(0, 0), H.Point(4, 0))
    local pout = T.Collider(pin, H.Point(10, 10))
    pout:getCentroid()
    pin:translate(1, 3) -- (1, 3) and (5, 3)
    x, y = pout:getCentroid()
    assert.near((1 + 5 + 10) / 3, x, 1e-12)
    assert.near((3 + 3 + 10) / 3, y, 1e-12)
  end)
end)
