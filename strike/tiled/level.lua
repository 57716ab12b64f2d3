--- S.tiled: a Tiled map's collidable objects and tiles as bodies in a space (docs/tiled.md).
--- This file walks the layers and assembles the level; strike/tiled/map.lua reads the format,
--- strike/tiled/shapes.lua places the objects and tiles, and strike/tiled/merge.lua merges a
--- tile layer's full-square tiles into regions.
---
--- What collides: a layer, object or tileset tile whose custom property `collidable` is
--- true (the convention of Simple-Tiled-Implementation's plugins), the nearest definition
--- winning (an object's over its tile's, over its layer's, over its group layers'), and the
--- layers named in opts.layers (collidable unless a nearer definition says false). Hidden
--- layers are skipped unless named (or inside a named group); text objects unless they are
--- themselves collidable. Loading is all or nothing: every body is built first, and only
--- then added to the space (and taken out again if adding fails).
local ROOT = (...):match('^(.-)%.tiled%.[^%.]+$')
local map = require(ROOT .. '.tiled.map')
local shapes = require(ROOT .. '.tiled.shapes')
local merge = require(ROOT .. '.tiled.merge')
local check = require(ROOT .. '.check')
local reserved = require(ROOT .. '.reserved')
local Collider = require(ROOT .. '.colliders.Collider')

local fail, describe, number, whole = map.fail, check.describe, map.number, map.whole
local properties, inherit, flags, tileOf = map.properties, map.inherit, map.flags, map.tileOf
local compose, translation, frame = shapes.compose, shapes.translation, shapes.frame
local type, pcall, error, huge = type, pcall, error, math.huge

local M = {}

---@class strike.Level
---@field bodies table[] every body added to the space, in map order
---@field byId table the body made from each Tiled object, by the object's id
---@field objectOf table for each body, the Tiled object it came from, or for tiles {layer =, tile =, ...}
---@field space strike.Space the space the bodies are in
local Level = {}
Level.__index = Level

--- Take every body of the level that is still in its space out of it. Returns the level.
---@return strike.Level
function Level:remove()
  if getmetatable(self) ~= Level then
    check.fail(('strike.tiled: level:remove: called with \'.\' instead of \':\' (self is %s); call it with'
      .. ' \':\''):format(describe(self)))
  end
  local space, bodies = self.space, self.bodies
  for i = #bodies, 1, -1 do
    local b = bodies[i]
    if space:has(b) then space:remove(b) end
  end
  return self
end

-- A body from its parts (shapes and colliders just built): the one collider, or a Collider
-- holding them.
local function bodyOf(parts)
  if #parts == 1 and parts[1]._shapes then return parts[1] end
  return Collider._of(parts)
end

-- The error `err` of building something for `where`, raised again: an error of
-- strike.tiled's own as it is (it names its place already); any other (a constructor's:
-- strike.Concave refusing a polygon that crosses itself) naming `where` first.
local function raise(where, err)
  if type(err) == 'string' and not err:find(map.FNAME .. ': ', 1, true) then
    fail(where, (err:gsub('^.-:%d+: ', '', 1)))
  end
  error(err, 0)
end

-- Run build(...) for `where`, raising its error as `raise` does.
local function protected(where, build, ...)
  local ok, res, more = pcall(build, ...)
  if ok then return res, more end
  raise(where, res)
end

local function record(out, body, obj, rec)
  local n = out.n + 1
  out.n = n
  out.bodies[n], out.objects[n], out.options[n] = body, obj, map.options(rec)
end

-- Objects ------------------------------------------------------------------------------------

-- How far a tile object's (x, y) is from its box's top-left corner, in parts of its width and
-- height, per alignment (Tiled: alignmentOffset; unspecified is bottomleft on orthogonal maps).
local ALIGN = {
  unspecified = { 0, 1 }, topleft = { 0, 0 }, top = { 0.5, 0 }, topright = { 1, 0 }, left = { 0, 0.5 },
  center = { 0.5, 0.5 }, right = { 1, 0.5 }, bottomleft = { 0, 1 }, bottom = { 0.5, 1 }, bottomright = { 1, 1 },
}

-- The properties record of a tileset tile (cached per tile).
local function tileRecord(cache, tile, where)
  if not tile then return map.NONE end
  local rec = cache[tile]
  if not rec then
    rec = properties(tile.properties, where)
    cache[tile] = rec
  end
  return rec
end

-- Append the parts of a tile placed by P (from its image's coordinates): its collision shapes,
-- or its box. `rec` is the tile's body's record (for oneway).
local function addTileParts(parts, P, tile, tw, th, rec, where)
  local children = map.tileShapes(tile, where)
  if not children then
    shapes.addBox(parts, P, tw, th)
    return
  end
  for i = 1, #children do
    local child = children[i]
    if type(child) ~= 'table' then
      fail(where, ('the tile\'s collision shape #%d must be an object table, got %s'):format(i, describe(child)))
    end
    local cwhere = map.text(where) .. ', collision shape ' .. map.objectName(child, i)
    local kind = shapes.kind(child, cwhere)
    cwhere = map.text(where) .. ', collision shape ' .. map.objectName(child, i, kind)
    if kind == 'tile' then fail(cwhere, 'a tile\'s collision shape cannot be a tile (it has a gid)') end
    local own = properties(child.properties, cwhere)
    if own.collidable ~= false and (kind ~= 'text' or own.collidable == true) then
      local r = inherit(own, rec)
      protected(cwhere, shapes.add, parts, child, kind, compose(P, frame(child, cwhere)), r.oneway == true, cwhere)
    end
  end
end

local function buildObject(obj, kind, P, oneway, where)
  local parts = {}
  shapes.add(parts, obj, kind, P, oneway, where)
  return bodyOf(parts)
end

local function buildTileObject(P, tile, tw, th, rec, where)
  local parts = {}
  addTileParts(parts, P, tile, tw, th, rec, where)
  if #parts == 0 then return false end
  return bodyOf(parts)
end

local function loadObjects(entry, sets, out, tileRecs)
  local objs = entry.layer.objects
  if objs == nil then return end
  if type(objs) ~= 'table' then fail(entry.where, ('objects must be a list, got %s'):format(describe(objs))) end
  local T = translation(entry.offx, entry.offy)
  local place = map.place(entry.where) -- (each object's name in errors, written only for one)
  for i = 1, #objs do
    local obj = objs[i]
    if type(obj) ~= 'table' then
      fail(entry.where, ('objects[%d] must be an object table, got %s'):format(i, describe(obj)))
    end
    local where = map.at(place, obj, i, nil)
    local kind = shapes.kind(obj, where)
    map.at(place, obj, i, kind)
    local id = obj.id
    if id ~= nil then number(id, where, 'id') end
    local own = properties(obj.properties, where)
    if type(obj.template) == 'string' and inherit(own, entry.rec).collidable == true then
      -- (a JSON map keeps only what an instance of a template changes: the rest, its shape
      -- included, is in the template's file; the Lua export writes every object whole)
      fail(where, ('is an instance of the template %s, whose shape is in that file; strike reads no files: export'
        .. ' the map as Lua, which writes the object whole, or detach it (Tiled: Detach Template)')
        :format(map.quote(obj.template)))
    end
    local rec, body
    if kind == 'tile' then
      local gid = map.gid(obj.gid, where)
      local tid, fh, fv, fd = flags(gid)
      local ts, _, tile = tileOf(sets, tid, where, gid)
      rec = inherit(own, inherit(tileRecord(tileRecs, tile, where), entry.rec))
      if rec.collidable == true then
        local tw, th = map.tileSize(ts, tile, where)
        local w, h = number(obj.width, where, 'width', 0), number(obj.height, where, 'height', 0)
        if w < 0 or h < 0 then
          fail(where, ('width and height must be >= 0 (0: the tile\'s size), got %s and %s'):format(describe(w),
            describe(h)))
        end
        if w == 0 then w = tw end
        if h == 0 then h = th end
        local a = ALIGN[ts.align]
        local P = compose(T, compose(frame(obj, where),
          shapes.placement(-a[1] * w, -a[2] * h, w, h, tw, th, ts.ox, ts.oy, ts.fit, fh, fv, fd)))
        body = protected(where, buildTileObject, P, tile, tw, th, rec, where)
      end
    else
      rec = inherit(own, entry.rec)
      if rec.collidable == true and (kind ~= 'text' or own.collidable == true) then
        body = protected(where, buildObject, obj, kind, compose(T, frame(obj, where)), rec.oneway == true, where)
      end
    end
    if body then
      record(out, body, obj, rec)
      if id ~= nil then
        if out.byId[id] then fail(where, ('object id %s is used twice'):format(describe(id))) end
        out.byId[id] = body
      end
    end
  end
end

-- Tile layers ----------------------------------------------------------------------------------

-- The cells of a tile layer: a function cells(visit) calling visit(row, col0, data, base, count)
-- for each row's stretch of cells (col0 .. col0 + count - 1 are data[base + 1 .. base + count]),
-- rows in increasing order and the stretches of a row in increasing column order; and
-- gidAt(col, row).
local function fixedCells(layer, where)
  local W = whole(layer.width, where, 'width', 0, 2 ^ 31)
  local H = whole(layer.height, where, 'height', 0, 2 ^ 31)
  local data = layer.data
  if type(data) == 'string' then
    fail(where, ('its tiles are stored as %s%s; strike.tiled reads them as a list of gids: set the map\'s tile'
      .. ' layer format to CSV in Tiled (Map > Map Properties > Tile Layer Format)'):format(
      describe(layer.encoding or 'base64'), layer.compression and (' compressed with ' .. describe(layer.compression))
      or ''))
  end
  if type(data) ~= 'table' then fail(where, ('data must be a list of gids, got %s'):format(describe(data))) end
  if #data ~= W * H then
    fail(where, ('data has %d gids; a %d by %d layer has %d'):format(#data, W, H, W * H))
  end
  local function cells(visit)
    if W == 0 then return end -- (no cells, however many rows: a height of 2^31 is no loop)
    for r = 0, H - 1 do visit(r, 0, data, r * W, W) end
  end
  local function gidAt(c, r) return data[r * W + c + 1] end
  return cells, gidAt
end

local function chunkCells(layer, where)
  local chunks = layer.chunks
  if type(chunks) ~= 'table' then fail(where, ('chunks must be a list, got %s'):format(describe(chunks))) end
  local list, LIM = {}, 2 ^ 40
  for i = 1, #chunks do
    local ch = chunks[i]
    local cw = ('chunk %d'):format(i)
    if type(ch) ~= 'table' then fail(where, ('%s must be a table {x, y, width, height, data}, got %s'):format(cw,
      describe(ch))) end
    local x = whole(ch.x, where, cw .. '\'s x', -LIM, LIM)
    local y = whole(ch.y, where, cw .. '\'s y', -LIM, LIM)
    local w = whole(ch.width, where, cw .. '\'s width', 0, 2 ^ 31)
    local h = whole(ch.height, where, cw .. '\'s height', 0, 2 ^ 31)
    local data = ch.data
    if type(data) == 'string' then
      fail(where, ('%s stores its tiles as a string (base64); strike.tiled reads them as a list of gids: set the'
        .. ' map\'s tile layer format to CSV in Tiled (Map > Map Properties > Tile Layer Format)'):format(cw))
    end
    if type(data) ~= 'table' then fail(where, ('%s\'s data must be a list of gids, got %s'):format(cw,
      describe(data))) end
    if #data ~= w * h then
      fail(where, ('%s\'s data has %d gids; a %d by %d chunk has %d'):format(cw, #data, w, h, w * h))
    end
    if w > 0 and h > 0 then list[#list + 1] = { x = x, y = y, w = w, h = h, data = data, i = i } end
  end
  -- rows from the first chunk's top to the last one's bottom, skipping the rows no chunk
  -- covers; each row's chunks by column (chunks sorted by top row, then column, then index)
  table.sort(list, function(a, b)
    if a.y ~= b.y then return a.y < b.y end
    if a.x ~= b.x then return a.x < b.x end
    return a.i < b.i
  end)
  local function cells(visit)
    local active, nextChunk, n = {}, 1, #list
    local r = n > 0 and list[1].y or 0
    while nextChunk <= n or #active > 0 do
      if #active == 0 and list[nextChunk].y > r then r = list[nextChunk].y end
      local changed = false
      while nextChunk <= n and list[nextChunk].y <= r do
        active[#active + 1] = list[nextChunk]
        nextChunk, changed = nextChunk + 1, true
      end
      if changed then
        table.sort(active, function(a, b)
          if a.x ~= b.x then return a.x < b.x end
          return a.i < b.i
        end)
      end
      local kept = 0
      for k = 1, #active do
        local ch = active[k]
        if k > 1 and ch.x < active[k - 1].x + active[k - 1].w then
          fail(where, ('chunks %d and %d overlap (row %d)'):format(active[k - 1].i, ch.i, r))
        end
        visit(r, ch.x, ch.data, (r - ch.y) * ch.w, ch.w)
      end
      for k = 1, #active do -- (drop the chunks that end at this row)
        local ch = active[k]
        if ch.y + ch.h > r + 1 then
          kept = kept + 1
          active[kept] = ch
        end
      end
      for k = #active, kept + 1, -1 do active[k] = nil end
      r = r + 1
    end
  end
  local function gidAt(c, r)
    for k = 1, #list do
      local ch = list[k]
      if c >= ch.x and c < ch.x + ch.w and r >= ch.y and r < ch.y + ch.h then
        return ch.data[(r - ch.y) * ch.w + (c - ch.x) + 1]
      end
    end
  end
  return cells, gidAt
end

local function loadTiles(entry, tmap, sets, out, tileRecs)
  local layer, where = entry.layer, entry.where
  local gw, gh = tmap.tilewidth, tmap.tileheight
  local cells, gidAt
  if layer.chunks ~= nil then
    cells, gidAt = chunkCells(layer, where)
  else
    cells, gidAt = fixedCells(layer, where)
  end

  -- Each gid's class, once per layer: 0 (empty or not solid), a merge key > 0 (a full-square
  -- solid tile: its options and its box's offset from the cell), or -1 (a tile with shapes of
  -- its own, or not the grid's size: a body of its own, from info[gid]).
  local class, info = {}, {}
  local keyOf, keyRec, offx, offy, nkeys = {}, {}, {}, {}, 0
  local function classify(gid, c, r)
    local cwhere = ('%s, tile at column %s, row %s'):format(where, describe(c), describe(r))
    gid = map.gid(gid, cwhere)
    if gid == 0 then class[gid] = 0 return 0 end
    local tid, fh, fv, fd = flags(gid)
    local ts, _, tile = tileOf(sets, tid, cwhere, gid)
    local rec = inherit(tileRecord(tileRecs, tile, cwhere), entry.rec)
    if rec.collidable ~= true then class[gid] = 0 return 0 end
    local tw, th = map.tileSize(ts, tile, cwhere)
    local w, h = tw, th
    if ts.grid then w, h = gw, gh end
    local P0 = shapes.placement(0, gh - h, w, h, tw, th, ts.ox, ts.oy, ts.fit, fh, fv, fd)
    -- full-square: no shapes of its own (or one unrotated rectangle) that cover exactly one
    -- cell's size, axis-aligned
    local children = map.tileShapes(tile, cwhere)
    local x0, y0, x1, y1
    if not children then
      x0, y0, x1, y1 = shapes.axisBox(P0, tw, th)
    elseif #children == 1 and type(children[1]) == 'table' and children[1].gid == nil then
      local child = children[1]
      local own = properties(child.properties, cwhere)
      if shapes.kind(child, cwhere) == 'rectangle' and (child.rotation or 0) == 0 and own.collidable ~= false then
        local cx, cy = number(child.x, cwhere, 'x', 0), number(child.y, cwhere, 'y', 0)
        local P = compose(P0, translation(cx, cy))
        local cwid, chei = child.width, child.height
        if type(cwid) == 'number' and type(chei) == 'number' and cwid > 0 and chei > 0 then
          x0, y0, x1, y1 = shapes.axisBox(P, cwid, chei)
        end
      end
    end
    local k
    if x0 and x1 - x0 == gw and y1 - y0 == gh then
      local name = map.optionsKey(rec) .. '\2' .. x0 .. '\2' .. y0
      k = keyOf[name]
      if not k then
        nkeys = nkeys + 1
        k = nkeys
        keyOf[name], keyRec[k], offx[k], offy[k] = k, rec, x0 + entry.offx, y0 + entry.offy
      end
    else
      k = -1
      info[gid] = { P0 = P0, tile = tile, tw = tw, th = th, rec = rec }
    end
    class[gid] = k
    return k
  end

  local builder = merge.new()
  local own, nown = {}, 0 -- the cells with bodies of their own: col, row, gid
  -- (a stretch's runs are handed to the builder together: merge.lua runs interpreted, and a
  -- call into it for each run kept LuaJIT from compiling this loop)
  local from, to, keys = {}, {}, {}
  cells(function(r, c0, data, base, count)
    local runKey, runStart, nrun = 0, 0, 0
    for i = 1, count do
      local gid = data[base + i]
      local k = class[gid]
      if k == nil then k = classify(gid, c0 + i - 1, r) end
      if k ~= runKey then
        if runKey > 0 then
          nrun = nrun + 1
          from[nrun], to[nrun], keys[nrun] = runStart, c0 + i - 1, runKey
        end
        runKey, runStart = k, c0 + i - 1
      end
      if k < 0 then
        own[nown + 1], own[nown + 2], own[nown + 3] = c0 + i - 1, r, gid
        nown = nown + 3
      end
    end
    if runKey > 0 then
      nrun = nrun + 1
      from[nrun], to[nrun], keys[nrun] = runStart, c0 + count, runKey
    end
    builder:runs(r, from, to, keys, nrun) -- (a row met again, from its next chunk, continues)
  end)
  local nreg = builder:finish()

  -- the bodies in map order: by their first cell, row by row. The regions come in that
  -- order (merge: by their first rectangle), and so do the cells with bodies of their own:
  -- the two lists are merged.
  local function tileObject(gid, c, r, count)
    local ts, lid, tile = tileOf(sets, (flags(gid)), where, gid)
    return { layer = layer, tile = tile, tileset = ts.src, id = lid, gid = gid, x = c, y = r, tiles = count }
  end
  local q = 1
  local function regionsBefore(r, c) -- (every region whose first cell comes before (c, r))
    while q <= nreg do
      local c0, r0, _, _, key = builder:rect(builder:first(q))
      if r0 > r or (r0 == r and c0 > c) then return end
      local ok, body, count = pcall(builder.body, builder, q, offx, offy, gw, gh)
      if not ok then raise(('%s, the region of tiles from column %d, row %d'):format(where, c0, r0), body) end
      record(out, body, tileObject(gidAt(c0, r0), c0, r0, count), keyRec[key])
      q = q + 1
    end
  end
  for i = 1, nown, 3 do
    local c, r, gid = own[i], own[i + 1], own[i + 2]
    regionsBefore(r, c)
    local inf = info[gid]
    local cwhere = ('%s, tile at column %d, row %d'):format(where, c, r)
    local P = compose(translation(entry.offx + c * gw, entry.offy + r * gh), inf.P0)
    local body = protected(cwhere, buildTileObject, P, inf.tile, inf.tw, inf.th, inf.rec, cwhere)
    if body then record(out, body, tileObject(gid, c, r, 1), inf.rec) end
  end
  regionsBefore(huge, huge)
end

-- The entry point -------------------------------------------------------------------------

local OPTIONS = { layers = true }

local function checkArguments(tmap, space, opts)
  if type(tmap) ~= 'table' or reserved.classType(tmap) then
    fail(nil, ('argument 1 must be a Tiled map (the table of Tiled\'s Lua export, or a JSON map decoded into'
      .. ' tables), got %s'):format(check.what(tmap)))
  end
  if type(tmap.layers) ~= 'table' or tmap.tilewidth == nil then
    fail(nil, ('argument 1 must be a Tiled map (the table of Tiled\'s Lua export, or a JSON map decoded into'
      .. ' tables), got a table without %s'):format(type(tmap.layers) ~= 'table' and 'a list of layers (layers)'
      or 'a tile width (tilewidth)'))
  end
  if reserved.classType(space) ~= 'space' then
    fail(nil, ('argument 2 must be a space (S.pace()), got %s'):format(check.what(space)))
  end
  local named = {}
  if opts ~= nil then
    if type(opts) ~= 'table' then
      fail(nil, ('argument 3 (options) must be a table such as {layers = {\'Walls\'}}, got %s'):format(describe(opts)))
    end
    local unknown = check.unknownKey(opts, OPTIONS)
    if unknown ~= nil then fail(nil, ('unknown option %s (the option is layers)'):format(describe(unknown))) end
    local layers = opts.layers
    if layers ~= nil then
      if type(layers) ~= 'table' then
        fail(nil, ('options.layers must be a list of layer names, got %s'):format(describe(layers)))
      end
      local index = {}
      for i = 1, #layers do
        if type(layers[i]) ~= 'string' then
          fail(nil, ('options.layers[%d] must be a layer name (a string), got %s'):format(i, describe(layers[i])))
        end
        named[layers[i]], index[i] = true, true
      end
      local bad = check.unknownKey(layers, index) -- (a key that is not 1 .. #layers)
      if bad ~= nil then
        fail(nil, ('options.layers must be a list of layer names, got the key %s'):format(describe(bad)))
      end
    end
  end
  local orientation = tmap.orientation
  if orientation ~= nil and orientation ~= 'orthogonal' then
    fail(nil, ('the map is %s; strike.tiled loads orthogonal maps only'):format(
      type(orientation) == 'string' and orientation or describe(orientation)))
  end
  local function tileSize(field)
    local v = tmap[field]
    if type(v) ~= 'number' or v - v ~= 0 or v <= 0 then
      fail(nil, ('map.%s must be a finite number > 0, got %s'):format(field, describe(v)))
    end
  end
  tileSize('tilewidth')
  tileSize('tileheight')
  return named
end

--- Load a Tiled map into a space (docs/tiled.md): every collidable object and
--- tile as a body, in map order. Returns the level {bodies =, byId =, objectOf =, space =}
--- (level:remove() takes its bodies out again). An error names the layer and object or tile
--- at fault, and leaves the space as it was.
---@param tmap table
---@param space strike.Space
---@param opts table|nil
---@return strike.Level
function M.load(tmap, space, opts)
  local named = checkArguments(tmap, space, opts)
  local sets = map.tilesets(tmap)
  local entries, seen = map.layers(tmap, named)
  if opts and opts.layers then
    for i = 1, #opts.layers do
      if not seen[opts.layers[i]] then
        fail(nil, ('options.layers names %s, which is no layer of the map'):format(map.quote(opts.layers[i])))
      end
    end
  end
  local out = { n = 0, bodies = {}, objects = {}, options = {}, byId = {} }
  local tileRecs = {}
  for i = 1, #entries do
    local e = entries[i]
    if e.shown or e.named then
      if e.type == 'objectgroup' then
        loadObjects(e, sets, out, tileRecs)
      elseif e.type == 'tilelayer' then
        loadTiles(e, tmap, sets, out, tileRecs)
      elseif e.ownNamed or e.own.collidable == true then
        fail(e.where, 'is an image layer: it has no collision shapes to load (draw them on an object layer)')
      end
    end
  end
  -- all built: into the space, all or nothing
  local bodies, objectOf, n = out.bodies, {}, out.n
  local added = 0
  local ok, err = pcall(function()
    for i = 1, n do
      space:add(bodies[i], out.options[i])
      added = i
    end
  end)
  if not ok then
    for i = added, 1, -1 do space:remove(bodies[i]) end
    error(err, 0)
  end
  for i = 1, n do objectOf[bodies[i]] = out.objects[i] end
  return setmetatable({ bodies = bodies, byId = out.byId, objectOf = objectOf, space = space }, Level)
end

return M
