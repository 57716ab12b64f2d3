--- Reading a Tiled map for strike.tiled: the two table shapes a map comes in, its custom
--- properties, its tilesets and global tile ids, and the walk over its layers. Nothing here
--- builds a shape (strike/tiled/shapes.lua does), and every failure is an error naming the
--- layer, object or tile it is about, at the line that called S.tiled.
---
--- The format, from Tiled's documentation (github.com/mapeditor/tiled: docs/reference/
--- tmx-map-format.rst, json-map-format.rst, global-tile-ids.rst) and its Lua exporter
--- (src/plugins/lua/luaplugin.cpp), read for the facts only:
---   * A map has `orientation`, `tilewidth`, `tileheight`, `tilesets` and `layers`; an
---     infinite map (`infinite`) keeps a tile layer's cells in `chunks` ({x, y, width, height,
---     data}, x and y in tiles, possibly negative) instead of one `data` list.
---   * Layers: `type` is 'tilelayer', 'objectgroup', 'imagelayer' or 'group' (a group's
---     `layers` nest); `offsetx`, `offsety` in pixels, and a group's offsets and visibility
---     apply to every layer inside it. A tile layer's `x`, `y` are in tiles (always 0 in
---     practice). Parallax factors are a drawing effect and are not read.
---   * Custom properties: the Lua export writes `properties = {name = value}`; JSON writes a
---     list `[{name =, type =, value =}]`. Both are read.
---   * A global tile id (gid) keeps flags in its top bits: 0x80000000 flipped horizontally,
---     0x40000000 vertically, 0x20000000 anti-diagonally (x and y swapped, done first), and
---     0x10000000 (hexagonal maps' 120-degree turn, cleared here). The rest picks the tileset
---     with the largest `firstgid` not above it; 0 is an empty cell.
---   * A tileset has `tilewidth`, `tileheight`, `tilecount`, `tileoffset` {x, y} (pixels, y
---     down, added when drawing its tiles), `objectalignment`, `tilerendersize` ('grid': its
---     tiles drawn at the map's grid size), `fillmode` and `tiles`, the tiles that carry
---     something: `id`, `properties`, an image collection's own size, and the collision shapes
---     drawn in Tiled's tile collision editor in `objectGroup` (Lua) or `objectgroup` (JSON).
---     An external tileset (`filename` in Lua, `source` in JSON) is not in the map.
local ROOT = (...):match('^(.-)%.tiled%.[^%.]+$')
local check = require(ROOT .. '.check')

local describe, type, floor = check.describe, type, math.floor

local M = {}

M.FNAME = 'strike.tiled'

--- How an error names a place: `where` itself when it is a string; an object's place
--- (M.place) as 'layer "things", object 12 "door" (polygon)'.
---@param where string|table
---@return string
function M.text(where)
  if type(where) ~= 'table' then return where end
  return where[1] .. ', ' .. M.objectName(where[2], where[3], where[4])
end

--- A place that names an object of a layer in errors (M.text), for the objects of the layer
--- whose own place is `where`: M.at(place, obj, index, kind) moves it to each object in turn
--- (kind nil until known), so that the name is written only when an error needs it.
---@param where string the layer's place
---@return table
function M.place(where) return { where, false, 0, nil } end

--- Move a place (M.place) to an object. Returns the place.
---@param place table
---@param obj table
---@param index integer
---@param kind string|nil
---@return table
function M.at(place, obj, index, kind)
  place[2], place[3], place[4] = obj, index, kind
  return place
end

--- Raise `msg` about `where` (a layer, object or tile: a string, or an object's place), at
--- the line that called S.tiled.
---@param where string|table|nil nil: about the map itself
---@param msg string
function M.fail(where, msg)
  if where then
    check.fail(('%s: %s: %s'):format(M.FNAME, M.text(where), msg))
  end
  check.fail(('%s: %s'):format(M.FNAME, msg))
end
local fail = M.fail

--- `v` as a finite number, or an error naming `field` of `where`; nil gives `default`.
---@param v any
---@param where string|table|nil a place (map.text)
---@param field string
---@param default number|nil
---@return number
function M.number(v, where, field, default)
  if v == nil and default ~= nil then return default end
  if type(v) ~= 'number' or v - v ~= 0 then
    fail(where, ('%s must be a finite number, got %s'):format(field, describe(v)))
  end
  return v
end
local number = M.number

--- `v` as a whole number (a finite number with no fraction) from lo to hi.
---@param v any
---@param where string|table|nil a place (map.text)
---@param field string
---@param lo number
---@param hi number
---@return number
function M.whole(v, where, field, lo, hi)
  if type(v) ~= 'number' or v - v ~= 0 or v % 1 ~= 0 or v < lo or v > hi then
    -- (the bounds as whole numbers on every VM: 2^32 - 1 is a float on Lua 5.3+)
    fail(where, ('%s must be a whole number from %.0f to %.0f, got %s'):format(field, lo, hi, describe(v)))
  end
  return v
end
local whole = M.whole

-- How a layer, an object or a tile is named in errors.

--- A quoted name for errors.
---@param s any
---@return string
function M.quote(s)
  if type(s) ~= 'string' then return describe(s) end
  if #s > 40 then s = s:sub(1, 40) .. '...' end
  return ('%q'):format(s)
end
local quote = M.quote

--- How an object is named in errors: 'object 12 "door" (polygon)'.
---@param obj table
---@param index integer its place in its list
---@param shape string|nil
---@return string
function M.objectName(obj, index, shape)
  local id = type(obj) == 'table' and obj.id
  local s = type(id) == 'number' and ('object %s'):format(describe(id)) or ('object #%d'):format(index)
  local name = type(obj) == 'table' and obj.name
  if type(name) == 'string' and name ~= '' then s = s .. ' ' .. quote(name) end
  if shape then s = s .. ' (' .. shape .. ')' end
  return s
end

-- Properties ------------------------------------------------------------------------------

-- The properties strike.tiled reads, in the order it reads them (errors name the first bad
-- one, whatever `pairs` order), with what each must be.
local NAMES = { 'collidable', 'sensor', 'oneway', 'layer', 'mask', 'group' }
local KINDS = { collidable = 'boolean', sensor = 'boolean', oneway = 'boolean', layer = 'string', mask = 'string',
  group = 'integer' }
local WANT = {
  boolean = 'a boolean (a bool property in Tiled)',
  string = 'a string',
  integer = 'a whole number (an int property in Tiled)',
}

--- The record of no properties (shared; never written).
M.NONE = {}

-- Names separated by commas, spaces around them dropped: a mask's list of layer names.
local function names(s)
  local list = {}
  for part in (s .. ','):gmatch('([^,]*),') do
    local name = part:match('^%s*(.-)%s*$')
    if name ~= '' then list[#list + 1] = name end
  end
  return list
end

local function setProperty(rec, name, v, where)
  local kind = KINDS[name]
  local ok
  if kind == 'integer' then
    ok = type(v) == 'number' and v - v == 0 and v % 1 == 0
  else
    ok = type(v) == kind
  end
  if not ok then
    fail(where, ('property %s must be %s, got %s'):format(name, WANT[kind], describe(v)))
  end
  if name == 'mask' then
    v = names(v)
    if #v == 0 then v = false end -- (no names: no mask, every layer, as space:add's mask = false)
  end
  rec[name] = v
end

--- The properties strike.tiled reads from a `properties` table in either shape (Lua export:
--- name = value; JSON: a list of {name =, type =, value =}): a record with the fields
--- collidable, sensor, oneway (booleans), layer (a string), mask (a list of names, from the
--- comma-separated string; false for a string of no names: every layer) and group (a whole
--- number), each nil when not given. Other properties are the game's and are not read.
---@param props any
---@param where string|table a place (map.text)
---@return table
function M.properties(props, where)
  if props == nil then return M.NONE end
  if type(props) ~= 'table' then
    fail(where, ('properties must be a table, got %s'):format(describe(props)))
  end
  local rec = nil
  if props[1] ~= nil then
    for i = 1, #props do
      local p = props[i]
      if type(p) ~= 'table' or type(p.name) ~= 'string' then
        fail(where, ('properties[%d] must be a property {name =, type =, value =} (as a JSON map has them), got %s')
          :format(i, describe(p)))
      end
      if KINDS[p.name] then
        rec = rec or {}
        setProperty(rec, p.name, p.value, where)
      end
    end
  else
    for i = 1, #NAMES do
      local name = NAMES[i]
      local v = props[name]
      if v ~= nil then
        rec = rec or {}
        setProperty(rec, name, v, where)
      end
    end
  end
  return rec or M.NONE
end

--- The record of `own` over `parent`: each field from `own` when it has it, else from
--- `parent` (the nearest definition wins: an object's over its tile's, over its layer's, over
--- its groups').
---@param own table
---@param parent table
---@return table
function M.inherit(own, parent)
  if own == M.NONE then return parent end
  if parent == M.NONE then return own end
  local rec = {}
  for i = 1, #NAMES do
    local name = NAMES[i]
    local v = own[name]
    if v == nil then v = parent[name] end
    rec[name] = v
  end
  return rec
end

--- The options for space:add from a record: layer, mask, group, sensor (those given), or
--- nil when none is.
---@param rec table
---@return table|nil
function M.options(rec)
  if rec.layer == nil and rec.mask == nil and rec.group == nil and rec.sensor == nil then return nil end
  local mask = rec.mask
  if mask then
    local copy = {}
    for i = 1, #mask do copy[i] = mask[i] end
    mask = copy
  end
  return { layer = rec.layer, mask = mask, group = rec.group, sensor = rec.sensor } -- (mask false: every layer)
end

--- A key that tells two records' space options apart (equal keys: the same options).
---@param rec table
---@return string
function M.optionsKey(rec)
  local mask = rec.mask
  local sorted = {}
  if mask then
    for i = 1, #mask do sorted[i] = mask[i] end
    table.sort(sorted)
  end
  return table.concat({ tostring(rec.sensor), tostring(rec.layer), mask and table.concat(sorted, '\0') or '*',
    tostring(rec.group) }, '\1')
end

-- Tilesets and gids ---------------------------------------------------------------------

local F31, F30, F29, F28, F32 = 2 ^ 31, 2 ^ 30, 2 ^ 29, 2 ^ 28, 2 ^ 32

--- A gid's tile id and flags: `id, h, v, d` (flipped horizontally, vertically, diagonally;
--- the hexagonal flag 0x10000000 is cleared). The gid must be a whole number in [0, 2^32).
---@param gid number
---@return number id
---@return boolean h
---@return boolean v
---@return boolean d
function M.flags(gid)
  local h, v, d = false, false, false
  if gid >= F31 then h, gid = true, gid - F31 end
  if gid >= F30 then v, gid = true, gid - F30 end
  if gid >= F29 then d, gid = true, gid - F29 end
  if gid >= F28 then gid = gid - F28 end
  return gid, h, v, d
end

local function tilesetName(ts, i)
  local name = type(ts) == 'table' and ts.name
  if type(name) == 'string' and name ~= '' then return ('tileset %s'):format(quote(name)) end
  return ('tileset #%d'):format(i)
end

-- A positive finite number, or an error.
local function size(v, where, field)
  if type(v) ~= 'number' or v - v ~= 0 or v <= 0 then
    fail(where, ('%s must be a finite number > 0, got %s'):format(field, describe(v)))
  end
  return v
end

local ALIGN = {
  unspecified = true, topleft = true, top = true, topright = true, left = true, center = true, right = true,
  bottomleft = true, bottom = true, bottomright = true,
}

-- A tileset's record: what the loader reads of it, checked.
local function readTileset(ts, i)
  local where = tilesetName(ts, i)
  if type(ts) ~= 'table' then fail(nil, ('tilesets[%d] must be a table, got %s'):format(i, describe(ts))) end
  local rec = { src = ts, where = where }
  rec.first = whole(ts.firstgid, where, 'firstgid', 1, F28 - 1)
  local external = ts.filename or ts.source
  if ts.tilewidth == nil and external ~= nil then
    -- (its tiles are in another file, which strike does not read: it reads no files)
    rec.external = external
    return rec
  end
  rec.tw = size(ts.tilewidth, where, 'tilewidth')
  rec.th = size(ts.tileheight, where, 'tileheight')
  if ts.tilecount ~= nil then rec.count = whole(ts.tilecount, where, 'tilecount', 0, F28) end
  local off = ts.tileoffset
  if off ~= nil and type(off) ~= 'table' then
    fail(where, ('tileoffset must be a table {x =, y =}, got %s'):format(describe(off)))
  end
  rec.ox = off and number(off.x, where, 'tileoffset.x', 0) or 0
  rec.oy = off and number(off.y, where, 'tileoffset.y', 0) or 0
  local align = ts.objectalignment
  if align == nil then align = 'unspecified' end
  if not ALIGN[align] then
    fail(where, ('objectalignment must be one of Tiled\'s alignments (unspecified, topleft, top, topright, left,'
      .. ' center, right, bottomleft, bottom, bottomright), got %s'):format(describe(align)))
  end
  rec.align = align
  local render = ts.tilerendersize
  if render ~= nil and render ~= 'tile' and render ~= 'grid' then
    fail(where, ('tilerendersize must be \'tile\' or \'grid\', got %s'):format(describe(render)))
  end
  rec.grid = render == 'grid'
  local fill = ts.fillmode
  if fill ~= nil and fill ~= 'stretch' and fill ~= 'preserve-aspect-fit' then
    fail(where, ('fillmode must be \'stretch\' or \'preserve-aspect-fit\', got %s'):format(describe(fill)))
  end
  rec.fit = fill == 'preserve-aspect-fit'
  local byId = {}
  local tiles = ts.tiles
  if tiles ~= nil then
    if type(tiles) ~= 'table' then fail(where, ('tiles must be a list, got %s'):format(describe(tiles))) end
    for k = 1, #tiles do
      local t = tiles[k]
      if type(t) ~= 'table' then fail(where, ('tiles[%d] must be a table, got %s'):format(k, describe(t))) end
      local id = whole(t.id, where, ('tiles[%d].id'):format(k), 0, F28)
      if byId[id] then fail(where, ('tile id %d appears twice in its tiles'):format(id)) end
      byId[id] = t
    end
  end
  rec.byId = byId
  return rec
end

--- The map's tilesets, checked, in order of firstgid (an error for two with the same one).
---@param map table
---@return table[]
function M.tilesets(map)
  local list = map.tilesets
  if list == nil then return {} end
  if type(list) ~= 'table' then fail(nil, ('map.tilesets must be a list, got %s'):format(describe(list))) end
  local sets = {}
  for i = 1, #list do sets[i] = readTileset(list[i], i) end
  for i = 2, #sets do -- (insertion sort by firstgid: a handful of tilesets, stable)
    local s, j = sets[i], i - 1
    while j >= 1 and sets[j].first > s.first do
      sets[j + 1] = sets[j]
      j = j - 1
    end
    sets[j + 1] = s
  end
  for i = 2, #sets do
    if sets[i].first == sets[i - 1].first then
      fail(nil, ('%s and %s have the same firstgid, %d'):format(sets[i - 1].where, sets[i].where, sets[i].first))
    end
  end
  return sets
end

--- The tile of a gid: `tileset, localId, tile` (tile: the tileset's entry for it, or nil
--- when it lists none), or an error about `where` when no tileset has it. `id` is the gid
--- without its flags (M.flags).
---@param sets table[]
---@param id number
---@param where string|table a place (map.text)
---@param gid number the gid as given, for the message
---@return table tileset
---@return number localId
---@return table|nil tile
function M.tileOf(sets, id, where, gid)
  local lo, hi, found = 1, #sets, nil
  while lo <= hi do -- (the last tileset whose firstgid is not above id)
    local mid = floor((lo + hi) / 2)
    if sets[mid].first <= id then found, lo = mid, mid + 1 else hi = mid - 1 end
  end
  if not found then
    if #sets == 0 then fail(where, ('gid %s names a tile, but the map has no tileset'):format(describe(gid))) end
    fail(where, ('gid %s is below every tileset (the first starts at %d)'):format(describe(gid), sets[1].first))
  end
  local ts = sets[found]
  local lid = id - ts.first
  if ts.external then
    fail(where, ('gid %s is a tile of %s, which is in another file (%s); strike reads no files: embed the tileset'
      .. ' in the map (Tiled: Map > Embed Tileset) or load it into map.tilesets yourself')
      :format(describe(gid), ts.where, describe(ts.external)))
  end
  local tile = ts.byId[lid]
  local nextFirst = sets[found + 1] and sets[found + 1].first
  if not tile and ((ts.count and lid >= ts.count) or (nextFirst and id >= nextFirst)) then
    fail(where, ('gid %s is beyond every tileset (%s has gids %d to %d)'):format(describe(gid), ts.where, ts.first,
      ts.first + (ts.count or 1) - 1))
  end
  return ts, lid, tile
end

--- A gid from a layer's data or an object, checked: a whole number from 0 to 2^32 - 1.
---@param gid any
---@param where string|table a place (map.text)
---@return number
function M.gid(gid, where)
  return whole(gid, where, 'gid', 0, F32 - 1)
end

--- A tile's own size: an image collection's tile has its own (`width`, `height` in the Lua
--- export; `imagewidth`, `imageheight` in JSON), the others the tileset's.
---@param ts table
---@param tile table|nil
---@param where string|table a place (map.text)
---@return number w
---@return number h
function M.tileSize(ts, tile, where)
  if tile then
    local w, h = tile.width, tile.height
    if w == nil then w, h = tile.imagewidth, tile.imageheight end
    if w ~= nil or h ~= nil then return size(w, where, 'the tile\'s width'), size(h, where, 'the tile\'s height') end
  end
  return ts.tw, ts.th
end

--- A tile's collision shapes (the objects drawn in Tiled's tile collision editor), or nil.
---@param tile table|nil
---@param where string|table a place (map.text)
---@return table[]|nil
function M.tileShapes(tile, where)
  if not tile then return nil end
  local group = tile.objectGroup
  if group == nil then group = tile.objectgroup end
  if group == nil then return nil end
  if type(group) ~= 'table' or type(group.objects) ~= 'table' then
    fail(where, ('the tile\'s collision shapes (objectGroup) must be an object layer with a list of objects, got %s')
      :format(type(group) == 'table' and 'no objects list' or describe(group)))
  end
  if #group.objects == 0 then return nil end
  return group.objects
end

-- Layers --------------------------------------------------------------------------------

local TYPES = { tilelayer = true, objectgroup = true, imagelayer = true, group = true }

--- The map's layers in map order, group layers flattened: entries {layer =, where =, type =,
--- offx =, offy =, rec =, own =, shown =, named =, ownNamed =}: offx, offy the pixel offset
--- (the layer's and its groups', added up), rec its properties over its groups' (M.inherit),
--- own its own, shown false when it or a group holding it is hidden, named true when it or a
--- group holding it is in `named` (a set of layer names; its layers then count as
--- collidable: rec.collidable is true unless a nearer layer says otherwise), ownNamed when
--- it is. Also returns the set of the names it met.
---@param map table
---@param named table set of names
---@return table[] entries
---@return table seen
function M.layers(map, named)
  local out, seen, active = {}, {}, {}
  local tw = map.tilewidth
  local th = map.tileheight
  local function walk(list, path, offx, offy, rec, shown, isNamed, depth)
    local at = nil -- (the group holding the list, nil for the map's own)
    if path ~= '' then at = ('layer %s'):format(quote(path)) end
    if type(list) ~= 'table' then
      fail(at, ('%s must be a list of layers, got %s'):format(at and 'layers' or 'map.layers', describe(list)))
    end
    if active[list] then fail(nil, ('layer %s contains itself'):format(quote(path))) end
    active[list] = true
    for i = 1, #list do
      local layer = list[i]
      if type(layer) ~= 'table' then
        fail(at, ('%s[%d] must be a layer table, got %s'):format(at and 'layers' or 'map.layers', i, describe(layer)))
      end
      local name = layer.name
      local label = type(name) == 'string' and name or ('#' .. i)
      local full = path == '' and label or (path .. '/' .. label)
      local where = ('layer %s'):format(quote(full))
      local kind = layer.type
      if not TYPES[kind] then
        fail(where, ('type must be \'tilelayer\', \'objectgroup\', \'imagelayer\' or \'group\', got %s')
          :format(describe(kind)))
      end
      local ox = offx + number(layer.offsetx, where, 'offsetx', 0)
      local oy = offy + number(layer.offsety, where, 'offsety', 0)
      if kind == 'tilelayer' then
        ox = ox + number(layer.x, where, 'x', 0) * tw
        oy = oy + number(layer.y, where, 'y', 0) * th
      end
      local visible = layer.visible
      if visible ~= nil and type(visible) ~= 'boolean' then
        fail(where, ('visible must be a boolean, got %s'):format(describe(visible)))
      end
      local ownNamed = type(name) == 'string' and named[name] == true
      local here = isNamed or ownNamed
      if type(name) == 'string' then seen[name] = true end
      local own = M.properties(layer.properties, where)
      local r = M.inherit(own, rec)
      if ownNamed then
        -- (named: collidable, whatever the layer and its groups say; a layer inside a named
        -- group may still say otherwise)
        r = M.inherit({ collidable = true }, r)
      end
      local entry = { layer = layer, where = where, type = kind, offx = ox, offy = oy, rec = r,
        own = own, shown = shown and visible ~= false, named = here, ownNamed = ownNamed }
      if kind == 'group' then
        if depth > 200 then fail(where, 'groups nest more than 200 deep') end
        walk(layer.layers, full, ox, oy, r, entry.shown, here, depth + 1)
      else
        out[#out + 1] = entry
      end
    end
    active[list] = nil
  end
  walk(map.layers, '', 0, 0, M.NONE, true, false, 0)
  return out, seen
end

return M
