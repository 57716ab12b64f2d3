-- S.tiled, tile layers: full-square solid tiles merged into one body per connected region
-- (4-connected; holes kept), solid and ghost-free (containsPoint, rays, S.triking, space:move),
-- tiles with collision shapes flipped by their gid's flags, tile sizes, tile offsets, render
-- sizes, layer offsets and infinite maps (chunks). Every expectation is computed here from
-- the grid and Tiled's conventions (spec/helpers/tiled.lua), not with strike's code.
local S = require('strike')
local T = require('spec.helpers.tiled')

local abs, min, max, floor, sqrt = math.abs, math.min, math.max, math.floor, math.sqrt

-- A grid from strings: '.' empty, '#' gid 1, other letters gid 2, 3, ... ('a' = 2).
local function grid(rows)
  local data, w = {}, #rows[1]
  for r, row in ipairs(rows) do
    assert(#row == w)
    for c = 1, w do
      local ch = row:sub(c, c)
      data[(r - 1) * w + c] = ch == '.' and 0 or ch == '#' and 1 or (ch:byte() - ('a'):byte() + 2)
    end
  end
  return data, w, #rows
end

-- Load one collidable tile layer of 16 x 16 tiles from `rows`.
local function load(rows, fields, layerProps, layerFields)
  local data, w, h = grid(rows)
  local m = T.map(fields)
  if not (fields and fields.tilesets) then m.tilesets = { T.tileset(1, 16) } end
  m.layers = { T.tiles('ground', w, h, data, layerProps or { collidable = true }, layerFields) }
  local space = S.pace()
  return S.tiled(m, space), space, data, w, h
end

-- For each cell of the grid, the body holding its centre (queryPoint): exactly one for a
-- solid cell, none for an empty one. Returns the bodies by cell.
local function bodiesByCell(space, data, w, h, gw, gh, ox, oy)
  gw, gh, ox, oy = gw or 16, gh or 16, ox or 0, oy or 0
  local of = {}
  for r = 0, h - 1 do
    for c = 0, w - 1 do
      local hits, n = space:queryPoint(ox + (c + 0.5) * gw, oy + (r + 0.5) * gh)
      local i = r * w + c + 1
      if data[i] ~= 0 then
        assert.equals(1, n, ('cell %d, %d'):format(c, r))
        of[i] = hits[1]
      else
        assert.equals(0, n, ('cell %d, %d'):format(c, r))
      end
    end
  end
  return of
end

describe('S.tiled tile layers: merging', function()
  it('one body per connected region, holes kept: the cells of a region share one body, and only they', function()
    local rows = {
      '##########..',
      '#........#..',
      '#.######.#.#',
      '#.#....#.#.#',
      '#.#.##.#.#..',
      '#.######.#.#',
      '#........#.#',
      '##########.#',
    }
    local level, space, data, w, h = load(rows)
    local region, count = T.regions(data, w, h)
    assert.equals(count, #level.bodies)
    local of = bodiesByCell(space, data, w, h)
    for i = 1, w * h do
      for j = 1, w * h do
        if region[i] ~= 0 and region[j] ~= 0 then assert.equals(region[i] == region[j], of[i] == of[j]) end
      end
    end
    -- the ring with a hole is one body whose area is its tiles'
    local ring = of[1]
    local tiles = 0
    for i = 1, w * h do if region[i] == region[1] then tiles = tiles + 1 end end
    assert.equals(tiles * 256, ring:getArea())
    assert.is_false(ring:containsPoint(5 * 16 + 8, 3 * 16 + 8)) -- (a cell of the hole)
  end)

  it('tiles that meet only at a corner are two regions; tiles that share a side are one', function()
    assert.equals(2, #(load({ '#.', '.#' }).bodies))
    assert.equals(2, #(load({ '.#', '#.' }).bodies))
    assert.equals(1, #(load({ '##', '.#' }).bodies))
    assert.equals(1, #(load({ '#.', '##' }).bodies))
  end)

  it('a floor of 1,000 tiles is one body of one rectangle', function()
    local level = load({ ('#'):rep(1000) })
    assert.equals(1, #level.bodies)
    assert.equals(1, level.bodies[1]:getShapeCount())
    assert.same({ 0, 0, 16000, 16 }, { level.bodies[1]:getBounds() })
  end)

  it('tiles of other ids merge; tiles whose options differ (their own properties) do not', function()
    local ts = T.tileset(1, 16, { { id = 2, properties = { layer = 'ice' } },
      { id = 3, properties = { sensor = true } },
      { id = 4, properties = { collidable = false } } })
    local level, space = load({ '#a#bbb#cc#dd#' }, { tilesets = { ts } })
    -- '#' and 'a' merge; 'b' (ice) and 'c' (sensor) are regions of their own; 'd' is not solid
    assert.equals(6, #level.bodies)
    local layers, sensors = {}, {}
    for i, b in ipairs(level.bodies) do
      local layer, _, _, sensor = space:get(b)
      layers[i], sensors[i] = layer, sensor
    end
    assert.same({ 'default', 'ice', 'default', 'default', 'default', 'default' }, layers)
    assert.same({ false, false, false, true, false, false }, sensors)
    assert.same({ 0, 0, 48, 16 }, { level.bodies[1]:getBounds() })
  end)

  it('keeps the body count at the number of regions on a random 60 x 60 map, 45 % solid, two option sets', function()
    local PRNG = require('spec.helpers.prng')
    local rng = PRNG.new(PRNG.seedFromEnv(2201))
    local ts = T.tileset(1, 16, { { id = 1, properties = { layer = 'b' } } })
    local rows = {}
    for r = 1, 60 do
      local row = {}
      for c = 1, 60 do
        local u = rng:next()
        row[c] = u < 0.3 and '#' or u < 0.45 and 'a' or '.'
      end
      rows[r] = table.concat(row)
    end
    local level, space, data, w, h = load(rows, { tilesets = { ts } })
    local _, count = T.regions(data, w, h)
    assert.equals(count, #level.bodies, 'seed ' .. rng.seed)
    bodiesByCell(space, data, w, h)
  end)
end)

-- The region's outline edges (unit cell sides between a cell of the region and one outside
-- it), as segments in pixels.
local function outline(region, id, w, h)
  local segs = {}
  local function inR(c, r) return c >= 0 and c < w and r >= 0 and r < h and region[r * w + c + 1] == id end
  for r = 0, h - 1 do
    for c = 0, w - 1 do
      if inR(c, r) then
        if not inR(c, r - 1) then segs[#segs + 1] = { c, r, c + 1, r } end
        if not inR(c, r + 1) then segs[#segs + 1] = { c, r + 1, c + 1, r + 1 } end
        if not inR(c - 1, r) then segs[#segs + 1] = { c, r, c, r + 1 } end
        if not inR(c + 1, r) then segs[#segs + 1] = { c + 1, r, c + 1, r + 1 } end
      end
    end
  end
  for _, s in ipairs(segs) do
    for k = 1, 4 do s[k] = s[k] * 16 end
  end
  return segs
end

local function distanceToSegment(px, py, s)
  local ex, ey = s[3] - s[1], s[4] - s[2]
  local t = max(0, min(1, ((px - s[1]) * ex + (py - s[2]) * ey) / (ex * ex + ey * ey)))
  local dx, dy = px - (s[1] + t * ex), py - (s[2] + t * ey)
  return sqrt(dx * dx + dy * dy)
end

describe('S.tiled tile layers: a region is one solid', function()
  local rows = {
    '.#########.',
    '.###.#####.',
    '##########.',
    '.####..####',
    '.#######.#.',
    '...#####...',
  }
  local level, space, data, w, h = load(rows)
  local region = T.regions(data, w, h)
  local body = level.bodies[1]

  it('is one body of several rectangles', function()
    assert.equals(1, #level.bodies)
    assert.is_true(body:getShapeCount() > 3)
  end)

  it('holds every point strictly inside its tiles, on the faces between them and at their corners; not its outline',
    function()
      local function inR(c, r) return c >= 0 and c < w and r >= 0 and r < h and region[r * w + c + 1] == 1 end
      for r = 0, h do
        for c = 0, w do
          -- a corner of the grid: inside when the four cells about it are the region's
          local inside = inR(c - 1, r - 1) and inR(c, r - 1) and inR(c - 1, r) and inR(c, r)
          local on = inR(c - 1, r - 1) or inR(c, r - 1) or inR(c - 1, r) or inR(c, r)
          assert.equals(inside, body:containsPoint(c * 16, r * 16), ('corner %d, %d'):format(c, r))
          assert.equals(inside, space:queryPoint(c * 16, r * 16) ~= nil and select(2, space:queryPoint(c * 16,
            r * 16)) == 1, ('corner %d, %d (queryPoint)'):format(c, r))
          if not on then assert.is_false(body:containsPoint(c * 16, r * 16)) end
          -- the middle of the cell side below and right of this corner
          if c < w then
            local both = inR(c, r - 1) and inR(c, r)
            assert.equals(both, body:containsPoint(c * 16 + 8, r * 16), ('side %d, %d'):format(c, r))
            assert.equals(both, body:containsPoint(c * 16 + 3.25, r * 16), ('side %d, %d'):format(c, r))
          end
          if r < h then
            local both = inR(c - 1, r) and inR(c, r)
            assert.equals(both, body:containsPoint(c * 16, r * 16 + 8), ('side %d, %d'):format(c, r))
          end
        end
      end
    end)

  it('a ray from inside leaves where the region ends, never at a face between its rectangles', function()
    local function inR(c, r) return c >= 0 and c < w and r >= 0 and r < h and region[r * w + c + 1] == 1 end
    for r = 0, h - 1 do
      for c = 0, w - 1 do
        if inR(c, r) then
          for _, d in ipairs({ { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 } }) do
            -- the grid walk: cells along the ray until one is outside the region
            local k = 0
            while inR(c + d[1] * (k + 1), r + d[2] * (k + 1)) do k = k + 1 end
            local want = (k + 0.5) * 16
            local x, y = c * 16 + 8, r * 16 + 8
            local t, hx, hy, nx, ny = body:rayCast(x, y, d[1], d[2])
            assert.near(want, t, 1e-9)
            assert.near(x + d[1] * want, hx, 1e-9)
            assert.near(y + d[2] * want, hy, 1e-9)
            assert.same({ d[1], d[2] }, { nx, ny })
            local hit, dist = space:rayCast(x, y, d[1], d[2])
            assert.equals(body, hit)
            assert.near(want, dist, 1e-9)
          end
        end
      end
    end
  end)

  it('pushes a point inside it out by the shortest way, to its outline (S.triking)', function()
    local segs = outline(region, 1, w, h)
    for r = 0, h - 1 do
      for c = 0, w - 1 do
        if region[r * w + c + 1] == 1 then
          for _, p in ipairs({ { 8, 8 }, { 3, 5 }, { 12.5, 1 }, { 0.5, 15 } }) do
            local px, py = c * 16 + p[1], r * 16 + p[2]
            local want = math.huge
            for _, s in ipairs(segs) do want = min(want, distanceToSegment(px, py, s)) end
            local m = S.triking(body, S.hapes.Point(px, py))
            assert.is_truthy(m)
            assert.near(want, m.depth, 1e-9, ('(%g, %g)'):format(px, py))
          end
        end
      end
    end
  end)

  it('pushes a box sunk into it out of its top, never sideways at a face between its rectangles', function()
    -- the top row's cells 1-9 over the rows below, whose rectangles differ
    for x = 16 + 5, 10 * 16 - 5, 0.5 do
      for sink = 0.5, 4, 0.5 do
        local box = S.trikers.Rectangle(x, -5 + sink, 10, 10)
        local m = S.triking(body, box)
        assert.is_truthy(m)
        assert.near(0, m.nx, 1e-12)
        assert.near(-1, m.ny, 1e-12)
        assert.near(sink, m.depth, 1e-9)
      end
    end
  end)
end)

describe('S.tiled tile layers: the alternatives to rectangles with seams, and where they fall short', function()
  -- the region of an L of tiles: rows 0-1, a 3-tile bar over a 1-tile stem
  local level = load({ '###', '#..' })
  local body = level.bodies[1]

  it('S.tiled\'s region: inside on the face between its rectangles, a ray from inside leaves at its outline, and'
    .. ' a point inside is pushed out', function()
    assert.equals(2, body:getShapeCount())
    assert.is_true(body:containsPoint(8, 16))
    assert.near(8 + 16, body:rayCast(8, 8, 0, 1), 1e-12)
    assert.is_truthy(S.triking(body, S.hapes.Point(8, 20)))
  end)

  it('plain rectangles (no seams): the face between them is outside both, and a ray from inside stops there',
    function()
      local plain = S.trikers.Collider(S.hapes.Rectangle(24, 8, 48, 16), S.hapes.Rectangle(8, 24, 16, 16))
      assert.is_false(plain:containsPoint(8, 16))
      assert.near(8, plain:rayCast(8, 8, 0, 1), 1e-12)
    end)

  it('a chain loop around the outline: a surface, not a solid (a point inside is not inside, nor pushed out)',
    function()
      local loop = S.trikers.Chain({ 0, 0, 48, 0, 48, 16, 16, 16, 16, 32, 0, 32 }, true)
      assert.is_false(loop:containsPoint(8, 20))
      assert.is_false(S.triking(loop, S.hapes.Point(8, 20)))
      assert.is_false(S.triking(loop, S.trikers.Rectangle(8, 20, 4, 4)))
    end)

  it('one Concave per region: a region with a hole has no simple outline', function()
    -- a ring of 8 tiles around a hole, its outline cut to the hole and back (a keyhole)
    assert.has_error(function()
      S.trikers.Concave(0, 0, 48, 0, 48, 48, 0, 48, 0, 16, 16, 16, 16, 32, 32, 32, 32, 16, 0, 16)
    end)
    assert.equals(1, #load({ '###', '#.#', '###' }).bodies)
  end)
end)

describe('S.tiled tile layers: ghost-free walking', function()
  it('a box walks a floor of 1,000 tiles with space:move, pressed down each step, without a bump', function()
    local level, space = load({ ('#'):rep(1000) })
    assert.equals(1, #level.bodies)
    local box = space:add(S.trikers.Rectangle(8, -6.5, 12, 12))
    local x, y = box:getCentroid()
    local x0, y0 = space:move(box, x, y + 10)
    local steps = 0
    while x0 < 16000 - 20 do
      local ax, ay, cols, n = space:move(box, x0 + 3, y0 + 2)
      assert.near(x0 + 3, ax, 1e-9)
      assert.equals(y0, ay)
      for i = 1, n do assert.same({ 0, -1 }, { cols[i].nx, cols[i].ny }) end
      x0 = ax
      steps = steps + 1
    end
    assert.is_true(steps > 5000)
  end)

  it('and across floors of separate regions side by side (tiles of different options), and a floor with holes'
    .. ' underneath', function()
    local ts = T.tileset(1, 16, { { id = 1, properties = { layer = 'b' } } })
    local top, under = {}, {}
    for c = 1, 300 do
      top[c] = (floor((c - 1) / 7) % 2 == 0) and '#' or 'a'
      under[c] = (c % 5 == 0) and '.' or '#'
    end
    local level, space = load({ table.concat(top), table.concat(under), table.concat(under) }, { tilesets = { ts } })
    assert.is_true(#level.bodies > 40)
    local box = space:add(S.trikers.Rectangle(8, -6.5, 12, 12))
    local x0, y0 = space:move(box, 8, 5)
    while x0 < 300 * 16 - 20 do
      local ax, ay, cols, n = space:move(box, x0 + 3, y0 + 2)
      assert.near(x0 + 3, ax, 1e-9)
      assert.near(y0, ay, 1e-9)
      for i = 1, n do
        assert.near(0, cols[i].nx, 1e-12)
        assert.near(-1, cols[i].ny, 1e-12)
      end
      x0, y0 = ax, ay
    end
  end)
end)

describe('S.tiled tile layers: tiles with collision shapes, sizes and offsets', function()
  -- gid 1: a 16 x 32 tile with a collision polygon; gid 2: a full-cell collision rectangle;
  -- gid 3: one 1 px short; gid 4: a plain 16 x 32 tile
  local poly = T.points(0, 32, 16, 32, 16, 10, 4, 0)
  local function tileset(fields)
    return T.tileset(1, 8, {
      { id = 0, objectGroup = T.objects('', { T.object('polygon', { x = 0, y = 0, polygon = poly }) }) },
      { id = 1, objectGroup = T.objects('', { T.object('rectangle', { x = 0, y = 0, width = 16, height = 32 }) }) },
      { id = 2, objectGroup = T.objects('', { T.object('rectangle', { x = 0, y = 0, width = 16, height = 31 }) }) },
    }, fields or { tilewidth = 16, tileheight = 32 })
  end

  for _, f in ipairs({ { false, false, false }, { true, false, false }, { false, true, false }, { true, true, false },
    { false, false, true }, { true, false, true }, { false, true, true }, { true, true, true } }) do
    local fh, fv, fd = f[1], f[2], f[3]
    it(('a 16 x 32 tile\'s polygon flipped h=%s v=%s d=%s, on its cell\'s bottom-left corner'):format(tostring(fh),
      tostring(fv), tostring(fd)), function()
      local gid = 1 + (fh and T.H or 0) + (fv and T.V or 0) + (fd and T.D or 0)
      local m = T.map({ tilesets = { tileset() } })
      m.layers = { T.tiles('ground', 3, 3, { 0, 0, 0, 0, 0, 0, 0, gid, 0 }, { collidable = true },
        { offsetx = 5, offsety = -7 }) }
      local level = S.tiled(m, S.pace())
      assert.equals(1, #level.bodies)
      local want = {}
      for _, p in ipairs(poly) do
        local u, v, _, fh2 = T.flip(p.x, p.y, 16, 32, fh, fv, fd)
        -- the cell (1, 2): bottom-left corner (16, 48); the flipped image fh2 tall above it
        want[#want + 1] = { 5 + 16 + u, -7 + 48 - fh2 + v }
      end
      local got = {}
      for _, v in ipairs(T.vertices(level.bodies[1])) do got[#got + 1] = v end
      -- (a concave polygon is split: compare its outline's area and its points)
      local area = 0
      for i = 1, #want do
        local p, q = want[i], want[i % #want + 1]
        area = area + p[1] * q[2] - q[1] * p[2]
      end
      assert.near(abs(area) / 2, level.bodies[1]:getArea(), 1e-9)
      for _, wv in ipairs(want) do
        local found = false
        for _, g in ipairs(got) do
          if abs(g[1] - wv[1]) < 1e-9 and abs(g[2] - wv[2]) < 1e-9 then found = true end
        end
        assert.is_true(found, ('(%g, %g)'):format(wv[1], wv[2]))
      end
      local x0, y0, x1, y1 = level.bodies[1]:getBounds()
      for gx = x0 + 0.3, x1, 0.7 do
        for gy = y0 + 0.2, y1, 0.9 do
          assert.equals(T.inside(want, gx, gy), level.bodies[1]:containsPoint(gx, gy))
        end
      end
    end)
  end

  it('a tile bigger than the grid (16 x 32 on 16 x 16) is a body of its own, growing up from its cell', function()
    local m = T.map({ tilesets = { tileset() } })
    m.layers = { T.tiles('ground', 3, 2, { 0, 4, 4, 0, 4 + T.D, 0 }, { collidable = true }) }
    local level = S.tiled(m, S.pace())
    assert.equals(3, #level.bodies)
    assert.same({ 16, -16, 32, 16 }, { level.bodies[1]:getBounds() })
    assert.same({ 32, -16, 48, 16 }, { level.bodies[2]:getBounds() })
    -- flipped anti-diagonally: 32 wide and 16 tall, still on its cell's bottom-left corner
    assert.same({ 16, 16, 48, 32 }, { level.bodies[3]:getBounds() })
  end)

  it('a collision rectangle covering the whole cell merges like a plain tile; 1 px short, it does not', function()
    local ts = T.tileset(1, 8, {
      { id = 1, objectGroup = T.objects('', { T.object('rectangle', { x = 0, y = 0, width = 16, height = 16 }) }) },
      { id = 2, objectGroup = T.objects('', { T.object('rectangle', { x = 0, y = 0, width = 16, height = 15 }) }) },
      { id = 3, objectGroup = T.objects('', { T.object('rectangle', { x = 0, y = 1, width = 16, height = 16 }) }) },
    })
    local level = load({ '#a#', '#b#', '#c#' }, { tilesets = { ts } })
    -- '#' and 'a' are one region; 'b' and 'c' are bodies of their own
    assert.equals(3, #level.bodies)
    assert.same({ 0, 0, 48, 48 }, { level.bodies[1]:getBounds() })
    assert.same({ 16, 16, 32, 31 }, { level.bodies[2]:getBounds() })
    assert.same({ 16, 33, 32, 49 }, { level.bodies[3]:getBounds() })
  end)

  it('tilerendersize grid draws a tile at the grid\'s size: full-square, merged', function()
    local m = T.map({ tilesets = { T.tileset(1, 8, {}, { tilewidth = 16, tileheight = 32,
      tilerendersize = 'grid' }) } })
    m.layers = { T.tiles('ground', 3, 1, { 1, 1, 1 }, { collidable = true }) }
    local level = S.tiled(m, S.pace())
    assert.equals(1, #level.bodies)
    assert.same({ 0, 0, 48, 16 }, { level.bodies[1]:getBounds() })
    -- and with preserve-aspect-fit, the 16 x 32 image fits 8 x 16, centred in its cell
    m.tilesets[1].fillmode = 'preserve-aspect-fit'
    level = S.tiled(m, S.pace())
    assert.equals(3, #level.bodies)
    assert.same({ 4, 0, 12, 16 }, { level.bodies[1]:getBounds() })
  end)

  it('a tileset\'s tileoffset moves its tiles; tiles of two offsets are two regions', function()
    local m = T.map({ tilesets = { T.tileset(1, 4), T.tileset(5, 4, {}, { tileoffset = { x = 3, y = -2 } }) } })
    m.layers = { T.tiles('ground', 4, 1, { 1, 1, 5, 5 }, { collidable = true }, { offsetx = 100, offsety = 10 }) }
    local level = S.tiled(m, S.pace())
    assert.equals(2, #level.bodies)
    assert.same({ 100, 10, 132, 26 }, { level.bodies[1]:getBounds() })
    assert.same({ 135, 8, 167, 24 }, { level.bodies[2]:getBounds() })
  end)

  it('a layer\'s offset and its groups\' move its tiles, and the map\'s tile size sets the grid', function()
    local m = T.map({ tilewidth = 10, tileheight = 20, tilesets = { T.tileset(1, 4, {}, { tilewidth = 10,
      tileheight = 20 }) } })
    m.layers = { T.group('g', { T.tiles('ground', 2, 2, { 1, 0, 1, 1 }, { collidable = true }, { offsetx = 1,
      offsety = 2 }) }, {}, { offsetx = 30, offsety = 40 }) }
    local level = S.tiled(m, S.pace())
    local space = level.space
    assert.equals(1, #level.bodies)
    assert.same({ 31, 42, 51, 82 }, { level.bodies[1]:getBounds() })
    bodiesByCell(space, { 1, 0, 1, 1 }, 2, 2, 10, 20, 31, 42)
  end)
end)

describe('S.tiled tile layers: infinite maps', function()
  local function chunk(x, y, w, h, rows)
    local data = grid(rows)
    return { x = x, y = y, width = w, height = h, data = data }
  end

  it('merges a region across chunks, at negative coordinates too, and keeps chunks apart where cells are', function()
    local m = T.map({ infinite = true, tilesets = { T.tileset(1, 4) } })
    local layer = T.tiles('ground', 8, 4, nil, { collidable = true }, { startx = -4, starty = -2 })
    layer.data = nil
    layer.chunks = {
      chunk(0, 0, 4, 2, { '##..', '...#' }),
      chunk(-4, -2, 4, 2, { '....', '...#' }),
      chunk(-4, 0, 4, 2, { '..##', '....' }),
      chunk(0, -2, 4, 2, { '#...', '#..#' }),
      chunk(5, 0, 4, 2, { '#...', '....' }), -- (column 4 is in no chunk: apart)
    }
    m.layers = { layer }
    local space = S.pace()
    local level = S.tiled(m, space)
    -- the union, columns -4 .. 8, rows -2 .. 1
    local rows = {
      '....#........',
      '...##..#.....',
      '..####...#...',
      '.......#.....',
    }
    local data, w, h = grid(rows)
    local _, count = T.regions(data, w, h)
    assert.equals(count, #level.bodies)
    bodiesByCell(space, data, w, h, 16, 16, -64, -32)
    -- in map order: by first cell, row by row
    local firsts = {}
    for i, b in ipairs(level.bodies) do firsts[i] = { level.objectOf[b].x, level.objectOf[b].y } end
    assert.same({ { 0, -2 }, { 3, -1 }, { 5, 0 }, { 3, 1 } }, firsts)
  end)

  it('a chunk\'s run of tiles goes on into the next chunk to its right; a row no chunk covers parts regions', function()
    local m = T.map({ infinite = true, tilesets = { T.tileset(1, 4) } })
    local layer = T.tiles('ground', 8, 4, nil, { collidable = true })
    layer.data = nil
    layer.chunks = { chunk(0, 0, 2, 1, { '##' }), chunk(2, 0, 2, 1, { '##' }), chunk(0, 2, 4, 1, { '####' }) }
    m.layers = { layer }
    local level = S.tiled(m, S.pace())
    assert.equals(2, #level.bodies)
    assert.equals(1, level.bodies[1]:getShapeCount())
    assert.same({ 0, 0, 64, 16 }, { level.bodies[1]:getBounds() })
    assert.same({ 0, 32, 64, 48 }, { level.bodies[2]:getBounds() })
  end)
end)

describe('S.tiled tile layers: what is loaded', function()
  it('the layer\'s properties give its regions\' options; a tile\'s own win', function()
    local ts = T.tileset(1, 16, { { id = 1, properties = { mask = 'player', group = 0 } } })
    local level, space = load({ '#.a' }, { tilesets = { ts } }, { collidable = true, layer = 'ground', mask = 'a,b',
      group = 2, sensor = false })
    assert.same({ 'ground', { 'a', 'b' }, 2, false }, { space:get(level.bodies[1]) })
    assert.same({ 'ground', { 'player' }, 0, false }, { space:get(level.bodies[2]) })
  end)

  it('a mask of no names (an empty string, or commas and spaces) is no mask: every layer, over the layer\'s', function()
    local ts = T.tileset(1, 16, { { id = 1, properties = { mask = '' } }, { id = 2, properties = { mask = ' , ' } },
      { id = 3, properties = { mask = ' a ,, b c ' } } })
    local level, space = load({ '#.a.b.c' }, { tilesets = { ts } }, { collidable = true, mask = 'x' })
    local masks = {}
    for i, b in ipairs(level.bodies) do masks[i] = select(2, space:get(b)) or 'every layer' end
    assert.same({ { 'x' }, 'every layer', 'every layer', { 'a', 'b c' } }, masks)
  end)

  it('tiles collide by their tileset tile\'s collidable in a layer that is not collidable', function()
    local ts = T.tileset(1, 16, { { id = 1, properties = { collidable = true } } })
    local level = load({ '#a#a' }, { tilesets = { ts } }, {})
    assert.equals(2, #level.bodies)
    assert.same({ 16, 0, 32, 16 }, { level.bodies[1]:getBounds() })
  end)

  it('lists bodies in map order: by their first tile, row by row, left to right, regions and tiles with shapes mixed',
    function()
      local ts = T.tileset(1, 16, { { id = 1, objectGroup = T.objects('', {
        T.object('polygon', { polygon = T.points(0, 16, 16, 16, 16, 0) }) }) } })
      local level = load({ 'a##.a#', '.#a.##', 'a..a..' }, { tilesets = { ts } })
      local firsts = {}
      for i, b in ipairs(level.bodies) do firsts[i] = { level.objectOf[b].x, level.objectOf[b].y } end
      assert.same({ { 0, 0 }, { 1, 0 }, { 4, 0 }, { 5, 0 }, { 2, 1 }, { 0, 2 }, { 3, 2 } }, firsts)
    end)

  it('objectOf gives the layer, the tile, its gid and cell, and the region\'s tile count', function()
    local ts = T.tileset(1, 16, { { id = 0, properties = { kind = 'rock' } } })
    local level = load({ '.##', '.#.' }, { tilesets = { ts } })
    local o = level.objectOf[level.bodies[1]]
    assert.equals('tilelayer', o.layer.type)
    assert.equals('rock', o.tile.properties.kind)
    assert.same({ 1, 1, 0, 3 }, { o.gid, o.x, o.y, o.tiles })
    assert.equals(ts, o.tileset)
    assert.equals(0, o.id)
  end)

  it('hidden layers are skipped unless named in options.layers; a layer named there is collidable', function()
    local m = T.map({ tilesets = { T.tileset(1, 4) } })
    m.layers = { T.tiles('hidden', 2, 1, { 1, 1 }, { collidable = true }, { visible = false }),
      T.tiles('plain', 2, 1, { 1, 1 }, {}),
      T.group('hiddenGroup', { T.tiles('inside', 2, 1, { 1, 1 }, { collidable = true }) }, {}, { visible = false }) }
    assert.equals(0, #S.tiled(m, S.pace()).bodies)
    assert.equals(1, #S.tiled(m, S.pace(), { layers = { 'hidden' } }).bodies)
    assert.equals(1, #S.tiled(m, S.pace(), { layers = { 'plain' } }).bodies)
    assert.equals(1, #S.tiled(m, S.pace(), { layers = { 'hiddenGroup' } }).bodies)
    assert.equals(1, #S.tiled(m, S.pace(), { layers = { 'inside' } }).bodies)
    m.layers[2].properties = { collidable = false }
    assert.equals(1, #S.tiled(m, S.pace(), { layers = { 'plain' } }).bodies)
  end)

  it('a tile whose collision group is empty is its box; one whose shapes all say collidable = false is nothing',
    function()
      local ts = T.tileset(1, 16, { { id = 1, objectGroup = T.objects('', {}) }, { id = 2, objectGroup = T.objects('', {
        T.object('rectangle', { width = 4, height = 4, properties = { collidable = false } }) }) } })
      local level = load({ '#a#b' }, { tilesets = { ts } })
      assert.equals(1, #level.bodies)
      assert.same({ 0, 0, 48, 16 }, { level.bodies[1]:getBounds() })
    end)

  it('image layers are skipped, in a named group too; hidden objects are loaded', function()
    local m = T.map({ tilesets = { T.tileset(1, 4) } })
    m.layers = { T.group('all', { { type = 'imagelayer', name = 'sky', image = 'sky.png', properties = {} },
      T.objects('things', { T.object('point', { x = 1, y = 2, visible = false }) }) }) }
    local level = S.tiled(m, S.pace(), { layers = { 'all' } })
    assert.equals(1, #level.bodies)
  end)

  it('a layer 0 wide and 2^31 tall, or 2^31 wide and 0 tall, has no cells: nothing, at once', function()
    local m = T.map({ tilesets = { T.tileset(1, 4) } })
    m.layers = { T.tiles('tall', 0, 2 ^ 31, {}, { collidable = true }),
      T.tiles('wide', 2 ^ 31, 0, {}, { collidable = true }) }
    local t0 = os.clock()
    assert.equals(0, #S.tiled(m, S.pace()).bodies)
    assert.is_true(os.clock() - t0 < 1)
  end)

  it('group layers may nest 200 deep (201 is an error: spec/tiled_errors_spec.lua)', function()
    local m = T.map({ tilesets = { T.tileset(1, 4) } })
    local g = T.group('g', {})
    m.layers = { g }
    for _ = 1, 200 do
      local inner = T.group('g', {})
      g.layers[1] = inner
      g = inner
    end
    g.layers[1] = T.tiles('deep', 1, 1, { 1 }, { collidable = true })
    assert.equals(1, #S.tiled(m, S.pace()).bodies)
  end)

  it('the same map as JSON decodes it gives the same bodies', function()
    local ts = T.tileset(1, 16, { { id = 1, properties = { layer = 'b' } }, { id = 2, objectGroup = T.objects('', {
      T.object('polygon', { polygon = T.points(0, 16, 16, 16, 16, 0) }) }) } })
    local data = grid({ '##a#b', '#..ab', '#####' })
    data[5] = 3 + T.H + T.D
    local m = T.map({ tilesets = { ts } })
    m.layers = { T.tiles('ground', 5, 3, data, { collidable = true, mask = 'x' }, { offsetx = 3 }) }
    local function shot(mm)
      local space = S.pace()
      local list = {}
      for i, b in ipairs(S.tiled(mm, space).bodies) do list[i] = { T.vertices(b), { space:get(b) } } end
      return list
    end
    assert.same(shot(m), shot(T.json(m)))
  end)
end)
