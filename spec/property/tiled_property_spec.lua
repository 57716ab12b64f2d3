-- Property-based specs for S.tiled's tile layers: random grids of tiles of several kinds
-- (plain, other options, a sensor, not collidable, with a collision triangle), every tile
-- flipped at random, in random tile sizes and offsets, as one data list or as chunks. The
-- oracle is computed here from the grid alone: the regions by a flood fill, each cell's body
-- and options, what is inside at the cells' centres, sides and corners, where a ray from a
-- region's cell leaves it, and each triangle's corners flipped as Tiled's documentation says.
-- Reproduce a failure with STRIKE_SEED=<seed> (any VM); the message names the seed and case.
local S = require('strike')
local PRNG = require('spec.helpers.prng')
local budget = require('spec.helpers.budget')
local T = require('spec.helpers.tiled')

local abs = math.abs

local SEED = PRNG.seedFromEnv(20260422)
local CASES = 60

-- The tiles: gid 1 and 3 plain (one region kind), 2 on the space layer 'b', 5 a sensor,
-- 6 not collidable, 4 with a collision triangle (a body of its own).
local KEY = { [1] = 1, [3] = 1, [2] = 2, [5] = 3 }
local TRIANGLE = { 0, 1, 1, 1, 1, 0 } -- (fractions of the tile: its lower-right half)

local function tileset(tw, th)
  local tri = {}
  for i = 1, #TRIANGLE, 2 do tri[#tri + 1] = { x = TRIANGLE[i] * tw, y = TRIANGLE[i + 1] * th } end
  return T.tileset(1, 8, {
    { id = 1, properties = { layer = 'b' } },
    { id = 3, objectGroup = T.objects('', { T.object('polygon', { x = 0, y = 0, polygon = tri }) }) },
    { id = 4, properties = { sensor = true } },
    { id = 5, properties = { collidable = false } },
  }, { tilewidth = tw, tileheight = th })
end

local function case(rng, seed, n)
  local where = ('seed %d case %d'):format(seed, n)
  local w, h = rng:int(2, 12), rng:int(2, 9)
  local sizes = { 8, 10, 16, 24 }
  local gw, gh = sizes[rng:int(1, 4)], sizes[rng:int(1, 4)]
  if rng:next() < 0.5 then gh = gw end
  local offx, offy = rng:int(-50, 50), rng:int(-50, 50)
  local gids, keys, flips = {}, {}, {}
  for i = 1, w * h do
    local g = 0
    if rng:next() < 0.6 then g = rng:int(1, 6) end
    -- (flipped anti-diagonally, a tile that is not square is not full-square: the tiles
    -- spec covers it; here only square tiles are)
    local fh, fv, fd = rng:next() < 0.5, rng:next() < 0.5, gw == gh and rng:next() < 0.5
    gids[i] = g == 0 and 0 or g + (fh and T.H or 0) + (fv and T.V or 0) + (fd and T.D or 0)
    keys[i] = KEY[g] or 0
    flips[i] = { fh, fv, fd, g }
  end
  local m = T.map({ tilewidth = gw, tileheight = gh, tilesets = { tileset(gw, gh) } })
  local layer = T.tiles('ground', w, h, gids, { collidable = true }, { offsetx = offx, offsety = offy })
  -- as chunks half of the time: random cuts of the grid, the layer starting at a random
  -- (negative or positive) tile position, the layer's offset taking it back
  local c0, r0 = 0, 0
  if rng:next() < 0.5 then
    c0, r0 = rng:int(-5, 5), rng:int(-5, 5)
    local chunks = {}
    local cw, ch = rng:int(1, 4), rng:int(1, 4)
    for cy = 0, h - 1, ch do
      for cx = 0, w - 1, cw do
        local ww, hh = math.min(cw, w - cx), math.min(ch, h - cy)
        local data = {}
        for r = 0, hh - 1 do
          for c = 0, ww - 1 do data[r * ww + c + 1] = gids[(cy + r) * w + cx + c + 1] end
        end
        chunks[#chunks + 1] = { x = c0 + cx, y = r0 + cy, width = ww, height = hh, data = data }
      end
    end
    for i = #chunks, 2, -1 do -- (in any order)
      local j = rng:int(1, i)
      chunks[i], chunks[j] = chunks[j], chunks[i]
    end
    layer.data, layer.chunks = nil, chunks
    layer.offsetx, layer.offsety = offx - c0 * gw, offy - r0 * gh
  end
  m.layers = { layer }
  local space = S.pace()
  local level = S.tiled(m, space)

  local region, count = T.regions(keys, w, h)
  local triangles = 0
  for i = 1, w * h do if flips[i][4] == 4 then triangles = triangles + 1 end end
  assert.equals(count + triangles, #level.bodies, where .. ': bodies')

  local function at(c, r) return offx + c * gw, offy + r * gh end
  local function regionAt(c, r)
    if c < 0 or c >= w or r < 0 or r >= h then return 0 end
    return region[r * w + c + 1]
  end
  local bodyOf = {}
  local LAYER, SENSOR = { 'default', 'b', 'default' }, { false, false, true }
  for r = 0, h - 1 do
    for c = 0, w - 1 do
      local i = r * w + c + 1
      local x, y = at(c + 0.5, r + 0.5)
      local hits, k = space:queryPoint(x, y)
      if region[i] ~= 0 then
        assert.equals(1, k, ('%s: cell %d, %d'):format(where, c, r))
        local body = hits[1]
        if bodyOf[region[i]] then
          assert.equals(bodyOf[region[i]], body, ('%s: cell %d, %d'):format(where, c, r))
        else
          for _, other in pairs(bodyOf) do assert.are_not.equal(other, body) end
          bodyOf[region[i]] = body
        end
        local layerName, _, _, sensor = space:get(body)
        assert.same({ LAYER[keys[i]], SENSOR[keys[i]] }, { layerName, sensor }, where)
      elseif flips[i][4] == 4 then
        -- the triangle, flipped as global-tile-ids.rst says, on its cell
        local want = {}
        for t = 1, #TRIANGLE, 2 do
          local u, v, _, flippedH = T.flip(TRIANGLE[t] * gw, TRIANGLE[t + 1] * gh, gw, gh, flips[i][1], flips[i][2],
            flips[i][3])
          local bx, by = at(c, r + 1) -- (on the cell's bottom-left corner)
          want[#want + 1] = { bx + u, by - flippedH + v }
        end
        local found
        for _, b in ipairs(level.bodies) do
          local o = level.objectOf[b]
          if o.x == c0 + c and o.y == r0 + r then found = b end
        end
        assert.is_truthy(found, where)
        T.sameVertices(T.vertices(found), want, 1e-9, ('%s: triangle at %d, %d'):format(where, c, r))
      else
        assert.equals(0, k, ('%s: cell %d, %d'):format(where, c, r)) -- (empty or not collidable)
      end
    end
  end

  -- sides and corners: inside a region's body exactly when the cells about them are its own
  for r = 0, h do
    for c = 0, w do
      local id = regionAt(c, r)
      local body = bodyOf[id]
      local x, y = at(c, r)
      if id ~= 0 then
        local all = regionAt(c - 1, r - 1) == id and regionAt(c, r - 1) == id and regionAt(c - 1, r) == id
        assert.equals(all, body:containsPoint(x, y), ('%s: corner %d, %d'):format(where, c, r))
        local sx, sy = at(c + 0.5, r)
        assert.equals(regionAt(c, r - 1) == id, body:containsPoint(sx, sy), ('%s: side above %d, %d'):format(where, c,
          r))
        sx, sy = at(c, r + 0.5)
        assert.equals(regionAt(c - 1, r) == id, body:containsPoint(sx, sy), ('%s: side left of %d, %d'):format(where,
          c, r))
        -- a ray from the cell's centre leaves where the region does
        for _, d in ipairs({ { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 } }) do
          local k = 0
          while regionAt(c + d[1] * (k + 1), r + d[2] * (k + 1)) == id do k = k + 1 end
          local ox, oy = at(c + 0.5, r + 0.5)
          local want = (k + 0.5) * (d[1] ~= 0 and gw or gh)
          local t = body:rayCast(ox, oy, d[1], d[2])
          assert.is_true(t ~= nil and abs(t - want) <= 1e-9, ('%s: ray from %d, %d along %d, %d: %s, want %s')
            :format(where, c, r, d[1], d[2], tostring(t), tostring(want)))
        end
      end
    end
  end
end

describe('S.tiled property: random tile layers', function()
  it('regions, options, inside and outside, rays and flipped shapes agree with the grid', function()
    local rng = PRNG.new(SEED)
    budget.loop(CASES, function(n) case(rng, SEED, n) end)
  end)

  it('the same grid as one data list and as chunks gives the same bodies', function()
    local rng = PRNG.new(SEED + 1)
    budget.loop(CASES / 3, function(n)
      local w, h = rng:int(2, 12), rng:int(2, 9)
      local gids = {}
      for i = 1, w * h do gids[i] = rng:next() < 0.5 and rng:int(1, 5) or 0 end
      local m = T.map({ tilesets = { tileset(16, 16) } })
      m.layers = { T.tiles('ground', w, h, gids, { collidable = true }) }
      local chunked = T.copy(m)
      local chunks, cw, ch = {}, rng:int(1, 5), rng:int(1, 5)
      for cy = 0, h - 1, ch do
        for cx = 0, w - 1, cw do
          local ww, hh = math.min(cw, w - cx), math.min(ch, h - cy)
          local data = {}
          for r = 0, hh - 1 do
            for c = 0, ww - 1 do data[r * ww + c + 1] = gids[(cy + r) * w + cx + c + 1] end
          end
          chunks[#chunks + 1] = { x = cx, y = cy, width = ww, height = hh, data = data }
        end
      end
      chunked.layers[1].data, chunked.layers[1].chunks = nil, chunks
      local function shot(mm)
        local space = S.pace()
        local list = {}
        for i, b in ipairs(S.tiled(mm, space).bodies) do list[i] = { T.vertices(b), { space:get(b) } } end
        return list
      end
      assert.same(shot(m), shot(chunked), ('seed %d case %d'):format(SEED + 1, n))
    end)
  end)
end)

