--- Tiled maps for the S.tiled specs, written here from Tiled's documentation (the Lua
--- export's table shape, and the JSON shape a game gets by decoding a .tmj file), and the
--- geometry of Tiled's conventions computed independently of strike: rotations, tile flips
--- (anti-diagonal swap first, then horizontal, then vertical: docs/reference/
--- global-tile-ids.rst), alignment of tile objects, point-in-polygon, flood fills.
local T = {}

local rad, cos, sin, abs, floor = math.rad, math.cos, math.sin, math.abs, math.floor

T.H, T.V, T.D = 2 ^ 31, 2 ^ 30, 2 ^ 29

--- A map in the shape of Tiled's Lua export: 16 x 16 tiles, `width` x `height`, the given
--- tilesets and layers.
function T.map(fields)
  local m = {
    version = '1.10', luaversion = '5.1', tiledversion = '1.10.2', class = '', orientation = 'orthogonal',
    renderorder = 'right-down', width = 10, height = 10, tilewidth = 16, tileheight = 16, nextlayerid = 1,
    nextobjectid = 1, properties = {}, tilesets = {}, layers = {},
  }
  for k, v in pairs(fields or {}) do m[k] = v end
  return m
end

--- A tileset of 16 x 16 tiles starting at `first`, `count` tiles, its `tiles` entries.
function T.tileset(first, count, tiles, fields)
  local ts = {
    name = 'tiles' .. first, firstgid = first, class = '', tilewidth = 16, tileheight = 16, spacing = 0, margin = 0,
    columns = 8, image = 'tiles.png', imagewidth = 128, imageheight = 128, objectalignment = 'unspecified',
    tilerendersize = 'tile', fillmode = 'stretch', tileoffset = { x = 0, y = 0 },
    grid = { orientation = 'orthogonal', width = 16, height = 16 }, properties = {}, wangsets = {},
    tilecount = count or 64, tiles = tiles or {},
  }
  for k, v in pairs(fields or {}) do ts[k] = v end
  return ts
end

--- A tile layer: `data` row by row (gids), `w` wide.
function T.tiles(name, w, h, data, props, fields)
  local l = {
    type = 'tilelayer', x = 0, y = 0, width = w, height = h, id = 1, name = name, class = '', visible = true,
    opacity = 1, offsetx = 0, offsety = 0, parallaxx = 1, parallaxy = 1, properties = props or {},
    encoding = 'lua', data = data,
  }
  for k, v in pairs(fields or {}) do l[k] = v end
  return l
end

--- An object layer.
function T.objects(name, objects, props, fields)
  local l = {
    type = 'objectgroup', draworder = 'topdown', id = 2, name = name, class = '', visible = true, opacity = 1,
    offsetx = 0, offsety = 0, parallaxx = 1, parallaxy = 1, properties = props or {}, objects = objects,
  }
  for k, v in pairs(fields or {}) do l[k] = v end
  return l
end

--- A group layer.
function T.group(name, layers, props, fields)
  local l = {
    type = 'group', id = 3, name = name, class = '', visible = true, opacity = 1, offsetx = 0, offsety = 0,
    parallaxx = 1, parallaxy = 1, properties = props or {}, layers = layers,
  }
  for k, v in pairs(fields or {}) do l[k] = v end
  return l
end

local nextId = 0
--- An object as the Lua export writes it: shape, x, y, width, height, rotation, and the rest.
function T.object(shape, fields)
  nextId = nextId + 1
  local o = { id = nextId, name = '', type = '', shape = shape, x = 0, y = 0, width = 0, height = 0, rotation = 0,
    visible = true, properties = {} }
  for k, v in pairs(fields or {}) do o[k] = v end
  return o
end

--- Points {x =, y =} from a flat list.
function T.points(...)
  local flat, pts = { ... }, {}
  for i = 1, #flat, 2 do pts[#pts + 1] = { x = flat[i], y = flat[i + 1] } end
  return pts
end

local function copy(v)
  if type(v) ~= 'table' then return v end
  local c = {}
  for k, x in pairs(v) do c[k] = copy(x) end
  return c
end
T.copy = copy

-- A properties table as JSON has it: a list of {name, type, value}, sorted by name.
local function jsonProperties(props)
  local list = {}
  for name, value in pairs(props) do
    local t = type(value) == 'boolean' and 'bool' or type(value) == 'number' and (value % 1 == 0 and 'int' or 'float')
      or 'string'
    list[#list + 1] = { name = name, type = t, value = value }
  end
  table.sort(list, function(a, b) return a.name < b.name end)
  return list
end

local function jsonObject(o)
  o = copy(o)
  if o.properties then o.properties = jsonProperties(o.properties) end
  local shape = o.shape
  o.shape = nil
  if shape == 'ellipse' then o.ellipse = true
  elseif shape == 'point' then o.point = true
  elseif shape == 'capsule' then o.capsule = true
  elseif shape == 'text' then o.text = { text = o.text or 'text', wrap = true } end
  return o
end

local function jsonLayer(l)
  l = copy(l)
  l.properties = jsonProperties(l.properties or {})
  if l.objects then
    for i, o in ipairs(l.objects) do l.objects[i] = jsonObject(o) end
  end
  if l.layers then
    for i, c in ipairs(l.layers) do l.layers[i] = jsonLayer(c) end
  end
  if l.type == 'tilelayer' then l.encoding = nil end
  return l
end

--- The same map as a JSON map decodes: properties as lists, objects marked by fields instead
--- of `shape`, a tile's collision shapes in `objectgroup`.
function T.json(m)
  m = copy(m)
  m.properties = jsonProperties(m.properties or {})
  m.type, m.luaversion = 'map', nil
  for i, l in ipairs(m.layers) do m.layers[i] = jsonLayer(l) end
  for _, ts in ipairs(m.tilesets) do
    ts.properties = jsonProperties(ts.properties or {})
    for _, t in ipairs(ts.tiles or {}) do
      if t.properties then t.properties = jsonProperties(t.properties) end
      if t.objectGroup then
        t.objectgroup = jsonLayer(t.objectGroup)
        t.objectGroup = nil
      end
    end
  end
  return m
end

-- Geometry -----------------------------------------------------------------------------

--- (px, py) turned by `deg` degrees clockwise on a y-down screen about (ox, oy).
function T.rotate(px, py, deg, ox, oy)
  local c, s = cos(rad(deg)), sin(rad(deg))
  local dx, dy = px - ox, py - oy
  return ox + dx * c - dy * s, oy + dx * s + dy * c
end

--- A point (u, v) of a tile image w x h after the gid's flips, as global-tile-ids.rst says
--- them: the anti-diagonal flip first (x and y swapped: the image becomes h x w), then the
--- horizontal (x -> width - x) and the vertical (y -> height - y). Returns the point and the
--- flipped image's size.
function T.flip(u, v, w, h, fh, fv, fd)
  if fd then u, v, w, h = v, u, h, w end
  if fh then u = w - u end
  if fv then v = h - v end
  return u, v, w, h
end

--- The world vertices of every leaf of a body, as a flat list of {x, y}.
function T.vertices(body)
  local list = {}
  local function leaf(s)
    for i = 1, s:getVertexCount() do
      local x, y = s:getVertex(i)
      list[#list + 1] = { x, y }
    end
  end
  if body.elems then
    for s in body:elems() do leaf(s) end
  else
    leaf(body)
  end
  return list
end

--- Every point of `want` ({x, y} pairs) within tol of a vertex of `got`, and as many of
--- each: the same set of points.
function T.sameVertices(got, want, tol, what)
  tol = tol or 1e-9
  assert(#got == #want, ('%sexpected %d vertices, got %d'):format(what and (what .. ': ') or '', #want, #got))
  local used = {}
  for _, w in ipairs(want) do
    local found = false
    for i, g in ipairs(got) do
      if not used[i] and abs(g[1] - w[1]) <= tol and abs(g[2] - w[2]) <= tol then
        used[i], found = true, true
        break
      end
    end
    assert(found, ('%sno vertex near (%.12g, %.12g); got %s'):format(what and (what .. ': ') or '', w[1], w[2],
      (function()
        local s = {}
        for _, g in ipairs(got) do s[#s + 1] = ('(%.12g, %.12g)'):format(g[1], g[2]) end
        return table.concat(s, ' ')
      end)()))
  end
end

--- Is (x, y) strictly inside the polygon of points {x, y} (even-odd crossings; the caller
--- keeps away from its boundary)?
function T.inside(poly, x, y)
  local n, c = #poly, false
  for i = 1, n do
    local a, b = poly[i], poly[i % n + 1]
    if (a[2] > y) ~= (b[2] > y) then
      local t = (y - a[2]) / (b[2] - a[2])
      if x < a[1] + t * (b[1] - a[1]) then c = not c end
    end
  end
  return c
end

--- The regions of a grid of keys (key[r * w + c + 1], 0 empty): 4-connected cells of the same
--- key. Returns the region number of each cell (0 for empty) and the count.
function T.regions(keys, w, h)
  local region, count = {}, 0
  for i = 1, w * h do region[i] = 0 end
  for start = 1, w * h do
    if keys[start] ~= 0 and region[start] == 0 then
      count = count + 1
      local stack, top = { start }, 1
      region[start] = count
      while top > 0 do
        local i = stack[top]
        top = top - 1
        local c, r = (i - 1) % w, floor((i - 1) / w)
        local nb = { c > 0 and i - 1, c < w - 1 and i + 1, r > 0 and i - w, r < h - 1 and i + w }
        for k = 1, 4 do
          local j = nb[k]
          if j and keys[j] == keys[i] and region[j] == 0 then
            region[j] = count
            top = top + 1
            stack[top] = j
          end
        end
      end
    end
  end
  return region, count
end

return T
