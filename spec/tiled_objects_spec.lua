-- S.tiled, objects: every shape Tiled draws, where Tiled draws it (y down, rotation in degrees
-- clockwise about the object's (x, y)), tile objects with their alignment, scale, flips and
-- collision shapes, layer and group offsets, and the same map as a JSON map decodes. The
-- expected geometry is computed here from Tiled's conventions (spec/helpers/tiled.lua), not
-- with strike's code.
local S = require('strike')
local T = require('spec.helpers.tiled')

local pi, abs = math.pi, math.abs

-- Load one object layer (collidable) holding `objects`; returns the level and the space.
local function load(objects, fields, layerProps)
  local m = T.map(fields)
  m.layers = { T.objects('things', objects, layerProps or { collidable = true }) }
  local space = S.pace()
  return S.tiled(m, space), space, m
end

local function one(obj, fields)
  local level, space = load({ obj }, fields)
  assert.equals(1, #level.bodies)
  return level.bodies[1], level, space
end

-- The corners of the box (x, y, w, h) turned by deg about (x, y), as Tiled draws a rectangle.
local function corners(x, y, w, h, deg)
  local list = {}
  for _, p in ipairs({ { x, y }, { x + w, y }, { x + w, y + h }, { x, y + h } }) do
    list[#list + 1] = { T.rotate(p[1], p[2], deg, x, y) }
  end
  return list
end

local function leaves(body)
  local list = {}
  for s in body:elems() do list[#list + 1] = s end
  return list
end

describe('S.tiled objects: rectangles', function()
  for _, deg in ipairs({ 0, 30, 90, 180, 270, -45, 123.5, 720 }) do
    it(('are where Tiled draws them, turned %g degrees clockwise about (x, y)'):format(deg), function()
      local body = one(T.object('rectangle', { x = 40, y = 24, width = 30, height = 12, rotation = deg }))
      T.sameVertices(T.vertices(body), corners(40, 24, 30, 12, deg), 1e-9)
      assert.near(360, body:getArea(), 1e-9)
    end)
  end

  it('turned by a multiple of 90 degrees, are exactly axis-aligned (cos 90 degrees is 0, not 6e-17)', function()
    for _, deg in ipairs({ 90, 180, 270, -90, 450 }) do
      -- (long and near the origin, so that 6e-17 of the width would show)
      local body = one(T.object('rectangle', { x = 0.5, y = 24, width = 3e5, height = 12, rotation = deg }))
      local xs, ys = {}, {}
      for _, v in ipairs(T.vertices(body)) do xs[v[1]], ys[v[2]] = true, true end
      local nx, ny = 0, 0
      for _ in pairs(xs) do nx = nx + 1 end
      for _ in pairs(ys) do ny = ny + 1 end
      assert.same({ 2, 2 }, { nx, ny }, deg)
    end
    local body = one(T.object('rectangle', { x = 40, y = 24, width = 30, height = 12, rotation = 90 }))
    assert.same({ 28, 24, 40, 54 }, { body:getBounds() })
  end)

  it('are a rectangle of the object\'s size (S.hapes.Rectangle)', function()
    local body = one(T.object('rectangle', { x = 1, y = 2, width = 3, height = 4 }))
    local s = leaves(body)
    assert.equals(1, #s)
    assert.is_true(s[1]:is(S.hapes.Rectangle))
    assert.same({ 1, 2, 4, 6 }, { body:getBounds() })
  end)
end)

describe('S.tiled objects: ellipses', function()
  it('are a circle when round: centre and radius from the box', function()
    local body = one(T.object('ellipse', { x = 10, y = 20, width = 30, height = 30 }))
    local s = leaves(body)[1]
    assert.equals('circle', s:getKind())
    local cx, cy = s:getCentroid()
    assert.same({ 25, 35, 15 }, { cx, cy, s:getRadius() })
  end)

  it('turned about (x, y), a circle\'s centre turns with it', function()
    local body = one(T.object('ellipse', { x = 10, y = 20, width = 30, height = 30, rotation = 60 }))
    local s = leaves(body)[1]
    local cx, cy = s:getCentroid()
    local ex, ey = T.rotate(25, 35, 60, 10, 20)
    assert.near(ex, cx, 1e-9)
    assert.near(ey, cy, 1e-9)
    assert.equals(15, s:getRadius())
  end)

  it('are not a circle when the width and height differ by the least amount', function()
    local w = 30
    local h = w + w * 2 ^ -52 * 4
    assert.is_true(h ~= w)
    local s = leaves(one(T.object('ellipse', { x = 0, y = 0, width = w, height = h })))[1]
    assert.equals('polygon', s:getKind())
  end)

  for _, case in ipairs({ { 40, 20, 0 }, { 20, 40, 0 }, { 40, 20, 35 }, { 12, 90, 90 }, { 7, 3, -200 } }) do
    local w, h, deg = case[1], case[2], case[3]
    it(('%g x %g turned %g degrees: vertices on the ellipse, area within 1 %%, inside it'):format(w, h, deg), function()
      local x, y = 50, 60
      local body = one(T.object('ellipse', { x = x, y = y, width = w, height = h, rotation = deg }))
      local s = leaves(body)[1]
      local a, b = w / 2, h / 2
      local cx, cy = T.rotate(x + a, y + b, deg, x, y)
      local n = s:getVertexCount()
      assert.is_true(n >= 26) -- (26 segments are needed for 1 %: n sin(2 pi / n) / (2 pi) > 0.99)
      for i = 1, n do
        local px, py = s:getVertex(i)
        local u, v = T.rotate(px, py, -deg, cx, cy)
        assert.near(1, ((u - cx) / a) ^ 2 + ((v - cy) / b) ^ 2, 1e-9)
      end
      local ratio = s:getArea() / (pi * a * b)
      assert.is_true(ratio > 0.99 and ratio <= 1, 'area ratio ' .. ratio)
      if deg % 90 == 0 then
        local x0, y0, x1, y1 = s:getBounds()
        local ex0, ey0 = T.rotate(x, y, deg, x, y)
        local ex1, ey1 = T.rotate(x + w, y + h, deg, x, y)
        assert.near(math.min(ex0, ex1), x0, 1e-9)
        assert.near(math.min(ey0, ey1), y0, 1e-9)
        assert.near(math.max(ex0, ex1), x1, 1e-9)
        assert.near(math.max(ey0, ey1), y1, 1e-9)
      end
    end)
  end
end)

describe('S.tiled objects: polygons', function()
  local function check(obj, convex)
    local body = one(obj)
    local pts = {}
    for _, p in ipairs(obj.polygon) do
      pts[#pts + 1] = { T.rotate(obj.x + p.x, obj.y + p.y, obj.rotation, obj.x, obj.y) }
    end
    -- the area of the outline (shoelace), and every point of a grid inside exactly when the
    -- outline holds it
    local area = 0
    for i = 1, #pts do
      local p, q = pts[i], pts[i % #pts + 1]
      area = area + p[1] * q[2] - q[1] * p[2]
    end
    assert.near(abs(area) / 2, body:getArea(), 1e-9 * abs(area))
    local x0, y0, x1, y1 = body:getBounds()
    for gx = x0 - 2.3, x1 + 2, 1.37 do
      for gy = y0 - 2.1, y1 + 2, 1.41 do
        assert.equals(T.inside(pts, gx, gy), body:containsPoint(gx, gy), ('(%g, %g)'):format(gx, gy))
      end
    end
    assert.equals(convex and 1 or nil, convex and body:getShapeCount() or nil)
    if not convex then assert.is_true(body:is(S.trikers.Concave)) end
    return body
  end

  it('convex: one ConvexPolygon through the points, relative to (x, y)', function()
    local body = check(T.object('polygon', { x = 100, y = 50, polygon = T.points(0, 0, 40, -10, 60, 30, 10, 40) }),
      true)
    T.sameVertices(T.vertices(body), { { 100, 50 }, { 140, 40 }, { 160, 80 }, { 110, 90 } })
  end)

  it('convex with a straight corner (collinear points) and a repeated point: still one convex piece', function()
    check(T.object('polygon', { x = 0, y = 0, polygon = T.points(0, 0, 10, 0, 20, 0, 20, 0, 20, 20, 0, 20) }), true)
  end)

  it('a corner dented inward by 1e-9 is concave: S.trikers.Concave, its outline exactly', function()
    local body = check(T.object('polygon', { x = 5, y = 5, polygon = T.points(0, 0, 20, 0, 20, 20, 10, 20 - 1e-9, 0,
      20) }), false)
    assert.is_false(body:containsPoint(15, 25 - 0.75e-9))
    assert.is_true(body:containsPoint(15, 25 - 1.25e-9))
    -- and bulging outward by as much, or not at all, convex
    check(T.object('polygon', { x = 5, y = 5, polygon = T.points(0, 0, 20, 0, 20, 20, 10, 20 + 1e-9, 0, 20) }), true)
    check(T.object('polygon', { x = 5, y = 5, polygon = T.points(0, 0, 20, 0, 20, 20, 10, 20, 0, 20) }), true)
  end)

  it('concave: S.trikers.Concave, its outline exactly', function()
    check(T.object('polygon', { x = 5, y = 5, rotation = 33,
      polygon = T.points(0, 0, 40, 0, 40, 40, 30, 40, 30, 10, 10, 10, 10, 40, 0, 40) }), false)
  end)

  for _, deg in ipairs({ 0, 90, 17, -150 }) do
    it(('turned %g degrees about (x, y)'):format(deg), function()
      check(T.object('polygon', { x = 30, y = 40, rotation = deg, polygon = T.points(0, 0, 30, 5, 25, 25, -5, 20) }),
        true)
      check(T.object('polygon', { x = 30, y = 40, rotation = deg,
        polygon = T.points(0, 0, 30, 0, 15, 10, 30, 30, 0, 30) }), false)
    end)
  end
end)

describe('S.tiled objects: polylines', function()
  local line = function(props, extra)
    local o = T.object('polyline', { x = 0, y = 100, polyline = T.points(0, 0, 100, 0), properties = props })
    for k, v in pairs(extra or {}) do o[k] = v end
    return o
  end
  local function segments(body)
    local list = {}
    for s in body:elems() do
      assert.equals('chain', s:getKind())
      list[#list + 1] = { s:getEdge(1) }
    end
    return list
  end

  it('block from both sides: two chains through the points, one each way', function()
    local body = one(T.object('polyline', { x = 10, y = 20, polyline = T.points(0, 0, 30, 0, 50, 20) }))
    local segs = segments(body)
    assert.equals(4, #segs)
    local want = { { 10, 20, 40, 20 }, { 40, 20, 60, 40 }, { 60, 40, 40, 20 }, { 40, 20, 10, 20 } }
    for _, w in ipairs(want) do
      local found = false
      for _, g in ipairs(segs) do
        if g[1] == w[1] and g[2] == w[2] and g[3] == w[3] and g[4] == w[4] then found = true end
      end
      assert.is_true(found, table.concat(w, ', '))
    end
    local above, below = S.trikers.Rectangle(50, 95, 20, 20), S.trikers.Rectangle(50, 105, 20, 20)
    local floor = one(line())
    local m = S.triking(floor, above)
    assert.is_truthy(m)
    assert.near(-1, m.ny, 1e-12)
    m = S.triking(floor, below)
    assert.is_truthy(m)
    assert.near(1, m.ny, 1e-12)
  end)

  it('oneway = true: one chain, solid on its left as drawn: a floor drawn left to right stops bodies from above'
    .. ' and lets them through from below', function()
    local floor = one(line({ oneway = true }))
    assert.equals(1, floor:getShapeCount())
    local m = S.triking(floor, S.trikers.Rectangle(50, 95, 20, 20))
    assert.is_truthy(m)
    assert.near(-1, m.ny, 1e-12)
    assert.is_false(S.triking(floor, S.trikers.Rectangle(50, 105, 20, 20)))
    -- drawn right to left: the other way round
    local ceiling = one(T.object('polyline', { x = 0, y = 100, polyline = T.points(100, 0, 0, 0),
      properties = { oneway = true } }))
    assert.is_false(S.triking(ceiling, S.trikers.Rectangle(50, 95, 20, 20)))
    assert.near(1, S.triking(ceiling, S.trikers.Rectangle(50, 105, 20, 20)).ny, 1e-12)
  end)

  it('a two-sided polyline of 20 segments has no ghost bumps at its joints, from above or below', function()
    local pts = {}
    for k = 0, 20 do pts[#pts + 1] = { x = 16 * k, y = 0 } end
    local long = one(T.object('polyline', { x = 0, y = 100, polyline = pts }))
    for x = 8, 312, 1 do
      for _, side in ipairs({ -1, 1 }) do
        local m = S.triking(long, S.trikers.Rectangle(x, 100 + side * 4.5, 8, 10))
        assert.is_truthy(m)
        assert.near(0, m.nx, 1e-12)
        assert.near(side, m.ny, 1e-12)
        assert.near(0.5, m.depth, 1e-9)
      end
    end
    local level, space = load({ T.object('polyline', { x = 0, y = 100, polyline = pts }) })
    assert.equals(1, #level.bodies)
    local box = space:add(S.trikers.Rectangle(8, 90, 8, 10))
    local x0, y0 = space:move(box, 8, 120)
    while x0 < 300 do
      local ax, ay = space:move(box, x0 + 3, y0 + 2)
      assert.near(x0 + 3, ax, 1e-9)
      assert.equals(y0, ay)
      x0 = ax
    end
  end)

  it('oneway from the layer, and an object\'s own oneway = false over it', function()
    local level = load({ line(), line({ oneway = false }) }, nil, { collidable = true, oneway = true })
    assert.equals(1, level.bodies[1]:getShapeCount())
    assert.equals(2, level.bodies[2]:getShapeCount())
  end)

  it('a character lands on a one-way platform with space:move and jumps up through it', function()
    local level, space = load({ line({ oneway = true }) })
    local box = space:add(S.trikers.Rectangle(50, 80, 10, 10))
    local x, y = space:move(box, 50, 120) -- falling: lands on it
    assert.equals(50, x)
    assert.is_true(y < 95 and y > 95 - 1e-3)
    box:translateTo(50, 120)
    x, y = space:move(box, 50, 70) -- rising from below: passes
    assert.same({ 50, 70 }, { x, y })
    assert.equals(1, #level.bodies)
  end)
end)

describe('S.tiled objects: points, capsules, text', function()
  it('a point is a Point at (x, y)', function()
    local s = leaves(one(T.object('point', { x = 12.5, y = -3 })))[1]
    assert.is_true(s:is(S.hapes.Point))
    assert.same({ 12.5, -3 }, { s:getCentroid() })
  end)

  it('a capsule is the box with its shorter side\'s half as corner radius, turned about (x, y)', function()
    for _, case in ipairs({ { 20, 60, 0 }, { 60, 20, 0 }, { 60, 20, 30 }, { 20, 60, 90 } }) do
      local w, h, deg = case[1], case[2], case[3]
      local s = leaves(one(T.object('capsule', { x = 100, y = 100, width = w, height = h, rotation = deg })))[1]
      assert.equals('rounded', s:getKind())
      local r = math.min(w, h) / 2
      assert.near(r, s:getRounding(), 1e-9)
      -- its core: the segment between the centres of the two round ends
      local x1, y1 = s:getVertex(1)
      local x2, y2 = s:getVertex(2)
      local a, b
      if w > h then a, b = { 100 + r, 100 + r }, { 100 + w - r, 100 + r } else a, b = { 100 + r, 100 + r },
        { 100 + r, 100 + h - r } end
      local want = { { T.rotate(a[1], a[2], deg, 100, 100) }, { T.rotate(b[1], b[2], deg, 100, 100) } }
      T.sameVertices({ { x1, y1 }, { x2, y2 } }, want, 1e-9, ('%gx%g %g'):format(w, h, deg))
      assert.near(pi * r * r + (math.max(w, h) - 2 * r) * 2 * r, s:getArea(), 1e-9)
    end
    local round = leaves(one(T.object('capsule', { x = 0, y = 0, width = 10, height = 10 })))[1]
    assert.equals('circle', round:getKind())
  end)

  it('text is skipped, even in a collidable layer, unless itself collidable: then its box', function()
    local level = load({ T.object('text', { x = 0, y = 0, width = 50, height = 20, text = 'Hello' }),
      T.object('text', { x = 5, y = 6, width = 50, height = 20, text = 'wall', properties = { collidable = true } }) })
    assert.equals(1, #level.bodies)
    assert.same({ 5, 6, 55, 26 }, { level.bodies[1]:getBounds() })
  end)
end)

describe('S.tiled objects: tile objects', function()
  -- a 16 x 16 tile (gid 1) with no shapes, and gid 2 with a collision triangle (a slope up to
  -- the right) and a point; a 16 x 32 tile in an image collection (gid 10)
  local slope = { x = 0, y = 0, shape = 'polygon', rotation = 0, polygon = T.points(0, 16, 16, 16, 16, 0) }
  local function sets(fields)
    return {
      T.tileset(1, 8, { { id = 1, objectGroup = T.objects('', { T.object('polygon', slope) }) } }, fields),
      T.tileset(10, 2, { { id = 0, width = 16, height = 32, image = 'tall.png' } },
        { columns = 0, tilewidth = 16, tileheight = 32 }),
    }
  end

  -- Where Tiled draws the point (u, v) of a tile image tw x th for a tile object (x, y, w, h,
  -- rotation) with flips, bottom-left aligned (or `align`), with the tileset's offset.
  local function place(u, v, tw, th, o, fh, fv, fd, align, ox, oy)
    local fu, fv2 = T.flip(u, v, tw, th, fh, fv, fd)
    local sx, sy = o.width / tw, o.height / th
    local ax, ay = (align or { 0, 1 })[1], (align or { 0, 1 })[2]
    local px = o.x - ax * o.width + fu * sx + (ox or 0) * sx
    local py = o.y - ay * o.height + fv2 * sy + (oy or 0) * sy
    return T.rotate(px, py, o.rotation, o.x, o.y)
  end

  it('without collision shapes: the tile\'s box, (x, y) its bottom-left corner, scaled to the object\'s size',
    function()
    for _, o in ipairs({ T.object(nil, { gid = 1, x = 32, y = 64, width = 16, height = 16 }),
      T.object(nil, { gid = 1, x = 32, y = 64, width = 48, height = 20, rotation = 25 }),
      T.object(nil, { gid = 10, x = 5, y = 7, width = 16, height = 32, rotation = 90 }) }) do
      local body = one(o, { tilesets = sets() })
      local tw, th = 16, o.gid == 10 and 32 or 16
      local want = {}
      for _, p in ipairs({ { 0, 0 }, { tw, 0 }, { tw, th }, { 0, th } }) do
        want[#want + 1] = { place(p[1], p[2], tw, th, o) }
      end
      T.sameVertices(T.vertices(body), want, 1e-9)
    end
  end)

  it('a width and height of 0 (older maps) are the tile\'s size', function()
    local body = one(T.object(nil, { gid = 10, x = 5, y = 40, width = 0, height = 0 }), { tilesets = sets() })
    assert.same({ 5, 8, 21, 40 }, { body:getBounds() })
  end)

  for _, f in ipairs({ { false, false, false }, { true, false, false }, { false, true, false }, { true, true, false },
    { false, false, true }, { true, false, true }, { false, true, true }, { true, true, true } }) do
    local fh, fv, fd = f[1], f[2], f[3]
    it(('with collision shapes, flipped h=%s v=%s d=%s, scaled and turned'):format(tostring(fh), tostring(fv),
      tostring(fd)), function()
      local gid = 2 + (fh and T.H or 0) + (fv and T.V or 0) + (fd and T.D or 0)
      local o = T.object(nil, { gid = gid, x = 100, y = 200, width = 32, height = 32, rotation = 30 })
      local body = one(o, { tilesets = sets() })
      local want = {}
      for _, p in ipairs(slope.polygon) do want[#want + 1] = { place(p.x, p.y, 16, 16, o, fh, fv, fd) } end
      T.sameVertices(T.vertices(body), want, 1e-9)
    end)
  end

  it('the tileset\'s objectalignment places (x, y): every alignment Tiled has', function()
    local aligns = { topleft = { 0, 0 }, top = { 0.5, 0 }, topright = { 1, 0 }, left = { 0, 0.5 },
      center = { 0.5, 0.5 }, right = { 1, 0.5 }, bottomleft = { 0, 1 }, bottom = { 0.5, 1 }, bottomright = { 1, 1 },
      unspecified = { 0, 1 } }
    for _, name in ipairs({ 'topleft', 'top', 'topright', 'left', 'center', 'right', 'bottomleft', 'bottom',
      'bottomright', 'unspecified' }) do
      local o = T.object(nil, { gid = 1, x = 50, y = 50, width = 20, height = 10, rotation = 15 })
      local body = one(o, { tilesets = sets({ objectalignment = name }) })
      local want = {}
      for _, p in ipairs({ { 0, 0 }, { 16, 0 }, { 16, 16 }, { 0, 16 } }) do
        want[#want + 1] = { place(p[1], p[2], 16, 16, o, false, false, false, aligns[name]) }
      end
      T.sameVertices(T.vertices(body), want, 1e-9, name)
    end
  end)

  it('the tileset\'s tileoffset moves it, scaled with the tile', function()
    local o = T.object(nil, { gid = 2, x = 10, y = 40, width = 32, height = 16 })
    local body = one(o, { tilesets = sets({ tileoffset = { x = 3, y = -5 } }) })
    local want = {}
    for _, p in ipairs(slope.polygon) do
      want[#want + 1] = { place(p.x, p.y, 16, 16, o, false, false, false, nil, 3, -5) }
    end
    T.sameVertices(T.vertices(body), want, 1e-12)
  end)

  it('a round collision ellipse stays a circle under a uniform scale and flips, and is stretched otherwise', function()
    local ts = T.tileset(1, 4, { { id = 0, objectGroup = T.objects('', {
      T.object('ellipse', { x = 2, y = 4, width = 8, height = 8 }) }) } })
    local body = one(T.object(nil, { gid = 1 + T.H + T.D, x = 0, y = 32, width = 32, height = 32 }),
      { tilesets = { ts } })
    local s = leaves(body)[1]
    assert.equals('circle', s:getKind())
    assert.equals(8, s:getRadius())
    -- the circle's centre (6, 8) in the image, flipped (d then h), doubled
    local u, v = T.flip(6, 8, 16, 16, true, false, true)
    assert.same({ 2 * u, 2 * v }, { s:getCentroid() })
    local stretched = leaves(one(T.object(nil, { gid = 1, x = 0, y = 16, width = 32, height = 16 }),
      { tilesets = { ts } }))[1]
    assert.equals('polygon', stretched:getKind())
    for i = 1, stretched:getVertexCount() do -- on the ellipse of semi-axes 8 and 4 about (12, 8)
      local x, y = stretched:getVertex(i)
      assert.near(1, ((x - 12) / 8) ^ 2 + ((y - 8) / 4) ^ 2, 1e-9)
    end
    assert.near(pi * 32 * 0.99359, stretched:getArea(), 0.01)
  end)

  it('a turned collision rectangle turns about its own (x, y) in the tile, then flips and scales with it: a'
    .. ' parallelogram when stretched unevenly', function()
    local ts = T.tileset(1, 4, { { id = 0, objectGroup = T.objects('', {
      T.object('rectangle', { x = 4, y = 5, width = 8, height = 4, rotation = 30 }) }) } })
    for _, case in ipairs({ { 16, 16, false }, { 32, 32, true }, { 32, 16, true }, { 24, 40, false } }) do
      local w, h, fh = case[1], case[2], case[3]
      local o = T.object(nil, { gid = 1 + (fh and T.H or 0), x = 50, y = 60, width = w, height = h, rotation = -15 })
      local body = one(o, { tilesets = { ts } })
      local want = {}
      for _, p in ipairs({ { 4, 5 }, { 12, 5 }, { 12, 9 }, { 4, 9 } }) do
        local u, v = T.rotate(p[1], p[2], 30, 4, 5)
        want[#want + 1] = { place(u, v, 16, 16, o, fh, false, false) }
      end
      T.sameVertices(T.vertices(body), want, 1e-9, ('%g x %g'):format(w, h))
    end
  end)

  it('a collision capsule stays a capsule under a uniform scale; stretched unevenly, a polygon through its outline',
    function()
      local ts = T.tileset(1, 4, { { id = 0, objectGroup = T.objects('', {
        T.object('capsule', { x = 2, y = 4, width = 12, height = 6 }) }) } })
      local even = leaves(one(T.object(nil, { gid = 1, x = 0, y = 32, width = 32, height = 32 }),
        { tilesets = { ts } }))[1]
      assert.equals('rounded', even:getKind())
      assert.near(6, even:getRounding(), 1e-12)
      local s = leaves(one(T.object(nil, { gid = 1, x = 0, y = 16, width = 32, height = 16 }),
        { tilesets = { ts } }))[1]
      assert.equals('polygon', s:getKind())
      -- its box is the capsule's box stretched: x doubled
      local x0, y0, x1, y1 = s:getBounds()
      assert.near(4, x0, 1e-12)
      assert.near(28, x1, 1e-12)
      assert.near(4, y0, 1e-12)
      assert.near(10, y1, 1e-12)
      -- every vertex on the stretched outline: in the tile's coordinates, on a cap's arc or a side
      for i = 1, s:getVertexCount() do
        local x, y = s:getVertex(i)
        local u, v = x / 2, y -- (back in the tile)
        local cx = math.max(5, math.min(11, u))
        assert.near(3, math.sqrt((u - cx) ^ 2 + (v - 7) ^ 2), 1e-9)
      end
      assert.near(2 * (6 * 6 + math.pi * 9), s:getArea(), 0.05 * 2 * (6 * 6 + math.pi * 9))
    end)

  it('a one-way collision line of a flipped tile keeps its solid side where the flipped tile shows it', function()
    local ts = T.tileset(1, 4, { { id = 0, objectGroup = T.objects('', {
      T.object('polyline', { x = 0, y = 8, polyline = T.points(0, 0, 16, 0), properties = { oneway = true } }) }) } })
    local up = one(T.object(nil, { gid = 1 + T.H, x = 0, y = 16, width = 16, height = 16 }), { tilesets = { ts } })
    assert.near(-1, S.triking(up, S.trikers.Rectangle(8, 6, 4, 6)).ny, 1e-12)
    local down = one(T.object(nil, { gid = 1 + T.V, x = 0, y = 16, width = 16, height = 16 }), { tilesets = { ts } })
    assert.is_false(S.triking(down, S.trikers.Rectangle(8, 6, 4, 6)))
    assert.near(1, S.triking(down, S.trikers.Rectangle(8, 10, 4, 6)).ny, 1e-12)
  end)

  it('the tile\'s properties count between the object\'s and the layer\'s', function()
    local ts = T.tileset(1, 4, { { id = 0, properties = { collidable = true, sensor = true, layer = 'coin' } } })
    local m = T.map({ tilesets = { ts } })
    m.layers = { T.objects('things', {
      T.object(nil, { id = 1, gid = 1, x = 0, y = 16, width = 16, height = 16 }),
      T.object(nil, { id = 2, gid = 1, x = 0, y = 16, width = 16, height = 16, properties = { sensor = false } }),
      T.object(nil, { id = 3, gid = 1, x = 0, y = 16, width = 16, height = 16, properties = { collidable = false } }),
    }, { layer = 'ignored', mask = 'player' }) }
    local space = S.pace()
    local level = S.tiled(m, space)
    assert.equals(2, #level.bodies)
    local layer, mask, _, sensor = space:get(level.byId[1])
    assert.same({ 'coin', { 'player' }, true }, { layer, mask, sensor })
    _, _, _, sensor = space:get(level.byId[2])
    assert.is_false(sensor)
    assert.is_nil(level.byId[3])
  end)
end)

describe('S.tiled objects: offsets', function()
  it('a layer\'s offset, and its groups\' added to it', function()
    local m = T.map()
    local o = T.object('rectangle', { x = 10, y = 20, width = 5, height = 5 })
    m.layers = { T.group('outer', { T.group('inner', { T.objects('things', { o }, { collidable = true },
      { offsetx = 1, offsety = 2 }) }, {}, { offsetx = 10, offsety = 20 }) }, {}, { offsetx = 100, offsety = 200 }) }
    local level = S.tiled(m, S.pace())
    assert.same({ 121, 242, 126, 247 }, { level.bodies[1]:getBounds() })
  end)

  it('a group\'s properties reach the layers inside it; a nearer layer\'s win', function()
    local m = T.map()
    m.layers = { T.group('walls', {
      T.objects('a', { T.object('rectangle', { x = 0, y = 0, width = 5, height = 5 }) }),
      T.objects('b', { T.object('rectangle', { x = 0, y = 0, width = 5, height = 5 }) }, { sensor = true, group = -2 }),
      T.objects('c', { T.object('rectangle', { x = 0, y = 0, width = 5, height = 5 }) }, { collidable = false }),
    }, { collidable = true, layer = 'wall', group = 3 }) }
    local space = S.pace()
    local level = S.tiled(m, space)
    assert.equals(2, #level.bodies)
    assert.same({ 'wall', nil, 3, false }, { space:get(level.bodies[1]) })
    assert.same({ 'wall', nil, -2, true }, { space:get(level.bodies[2]) })
  end)
end)

describe('S.tiled objects: a JSON map decoded into tables', function()
  it('gives the same bodies as the Lua export of the same map', function()
    local ts = T.tileset(1, 8, { { id = 1, properties = { layer = 'tile' }, objectGroup = T.objects('', {
      T.object('polygon', { polygon = T.points(0, 16, 16, 16, 16, 0) }),
      T.object('ellipse', { x = 1, y = 1, width = 4, height = 6 }) }) } })
    local m = T.map({ tilesets = { ts } })
    m.layers = { T.objects('things', {
      T.object('rectangle', { x = 1, y = 2, width = 3, height = 4, rotation = 10 }),
      T.object('ellipse', { x = 1, y = 2, width = 30, height = 40, rotation = 10, properties = { sensor = true } }),
      T.object('ellipse', { x = 1, y = 2, width = 30, height = 30 }),
      T.object('polygon', { x = 5, y = 6, polygon = T.points(0, 0, 30, 0, 15, 10, 30, 30, 0, 30) }),
      T.object('polyline', { x = 5, y = 6, polyline = T.points(0, 0, 30, 0, 40, 10), properties = { oneway = true } }),
      T.object('point', { x = 7, y = 8 }),
      T.object('capsule', { x = 7, y = 8, width = 10, height = 30 }),
      T.object('text', { x = 7, y = 8, width = 10, height = 30, properties = { collidable = true, mask = 'a, b' } }),
      T.object(nil, { gid = 2 + T.H, x = 50, y = 50, width = 32, height = 32, rotation = 45 }),
    }, { collidable = true, group = 4 }) }
    local function describeLevel(level, space)
      local list = {}
      for i, b in ipairs(level.bodies) do
        local layer, mask, group, sensor = space:get(b)
        list[i] = { T.vertices(b), b:getShapeCount(), { b:getBounds() }, b:getArea(), layer, mask, group, sensor,
          level.objectOf[b].id }
      end
      return list
    end
    local s1, s2 = S.pace(), S.pace()
    local lua = describeLevel(S.tiled(m, s1), s1)
    local json = describeLevel(S.tiled(T.json(m), s2), s2)
    assert.equals(9, #lua)
    assert.same(lua, json)
  end)
end)

describe('S.tiled objects: the level', function()
  it('lists bodies in map order, by object id, and the object each came from', function()
    local a = T.object('rectangle', { x = 0, y = 0, width = 5, height = 5 })
    local b = T.object('point', { x = 1, y = 1 })
    local skipped = T.object('rectangle', { x = 0, y = 0, width = 5, height = 5, properties = { collidable = false } })
    local c = T.object('ellipse', { x = 0, y = 0, width = 5, height = 5 })
    local level, space = load({ a, skipped, b, c })
    assert.equals(3, #level.bodies)
    assert.equals(3, space:count())
    local bodies = space:bodies()
    for i, body in ipairs(level.bodies) do assert.equals(bodies[i], body) end
    assert.same({ a, b, c }, { level.objectOf[level.bodies[1]], level.objectOf[level.bodies[2]],
      level.objectOf[level.bodies[3]] })
    assert.equals(level.bodies[2], level.byId[b.id])
    assert.is_nil(level.byId[skipped.id])
    assert.equals(space, level.space)
  end)

  it('remove() takes its bodies out of the space, and only those still in it', function()
    local level, space = load({ T.object('point', { x = 1, y = 1 }), T.object('point', { x = 2, y = 2 }) })
    local mine = space:add(S.trikers.Circle(0, 0, 1))
    space:remove(level.bodies[1])
    assert.equals(level, level:remove())
    assert.equals(1, space:count())
    assert.is_true(space:has(mine))
    level:remove()
    assert.equals(1, space:count())
  end)

  it('loads the same map the same way twice (nothing depends on pairs order)', function()
    local objects = {}
    for i = 1, 30 do
      objects[i] = T.object(({ 'rectangle', 'ellipse', 'point' })[i % 3 + 1], { x = i * 7, y = i * 3, width = i,
        height = 2 * i, rotation = i * 11, properties = { layer = 'l' .. i % 4, mask = 'x, y,z', group = i % 3 } })
    end
    local function snapshot()
      local space = S.pace()
      local level = S.tiled(T.map({ layers = { T.objects('things', objects, { collidable = true }) } }), space)
      local list = {}
      for i, b in ipairs(level.bodies) do list[i] = { T.vertices(b), { space:get(b) } } end
      return list
    end
    assert.same(snapshot(), snapshot())
  end)
end)
