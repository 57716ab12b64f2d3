-- S.tiled, bad input: every error is raised at the caller's line, names S.tiled and the layer,
-- object or tile at fault with what was expected and what was given, and leaves the space
-- exactly as it was (nothing added, even when the error comes after bodies were built).
local S = require('strike')
local T = require('spec.helpers.tiled')
local expect = require('spec.helpers.expect')

local nan, inf = 0 / 0, math.huge

-- A map with a bit of everything, valid: a tileset with a shaped tile, a collidable tile layer
-- and a collidable object layer in a group.
local function base()
  local m = T.map({ width = 3, height = 2, tilesets = { T.tileset(1, 8, {
    { id = 1, properties = { collidable = true }, objectGroup = T.objects('', {
      T.object('polygon', { id = 3, polygon = T.points(0, 16, 16, 16, 16, 0) }) }) } }) } })
  m.layers = {
    T.tiles('ground', 3, 2, { 1, 1, 0, 0, 2, 1 }, { collidable = true }),
    T.group('world', { T.objects('things', {
      T.object('rectangle', { id = 1, name = 'door', x = 1, y = 2, width = 3, height = 4 }),
      T.object('polygon', { id = 2, x = 1, y = 2, polygon = T.points(0, 0, 10, 0, 10, 10) }),
    }, { collidable = true }) }),
  }
  return m
end

describe('S.tiled errors', function()
  it('the base map loads (the cases below break one thing each)', function()
    local space = S.pace()
    assert.equals(5, #S.tiled(base(), space).bodies)
  end)

  -- { what is broken, function(map) breaking it, text the error must contain }
  local cases = {
    { 'orthogonal only: isometric', function(m) m.orientation = 'isometric' end,
      'strike.tiled: the map is isometric; strike.tiled loads orthogonal maps only' },
    { 'staggered', function(m) m.orientation = 'staggered' end, 'the map is staggered;' },
    { 'hexagonal', function(m) m.orientation = 'hexagonal' end, 'the map is hexagonal;' },
    { 'an orientation that is not a string', function(m) m.orientation = 3 end, 'the map is 3;' },
    { 'a tile width of 0', function(m) m.tilewidth = 0 end, 'map.tilewidth must be a finite number > 0, got 0' },
    { 'a NaN tile height', function(m) m.tileheight = nan end, 'map.tileheight must be a finite number > 0, got nan' },
    { 'tilesets not a list', function(m) m.tilesets = 'x' end, 'map.tilesets must be a list, got string "x"' },
    { 'a tileset not a table', function(m) m.tilesets[2] = 5 end, 'tilesets[2] must be a table, got 5' },
    { 'a bad firstgid', function(m) m.tilesets[1].firstgid = 0 end,
      'tileset "tiles1": firstgid must be a whole number from 1 to' },
    { 'two tilesets with one firstgid', function(m) m.tilesets[2] = T.tileset(1, 4, {}, { name = 'other' }) end,
      'tileset "tiles1" and tileset "other" have the same firstgid, 1' },
    { 'a tileset without a tile size', function(m) m.tilesets[1].tileheight = -16 end,
      'tileset "tiles1": tileheight must be a finite number > 0, got -16' },
    { 'a bad tilecount', function(m) m.tilesets[1].tilecount = 1.5 end, 'tilecount must be a whole number' },
    { 'a bad tileoffset', function(m) m.tilesets[1].tileoffset = 4 end,
      'tileoffset must be a table {x =, y =}, got 4' },
    { 'an infinite tileoffset', function(m) m.tilesets[1].tileoffset = { x = inf, y = 0 } end,
      'tileoffset.x must be a finite number, got inf' },
    { 'an unknown objectalignment', function(m) m.tilesets[1].objectalignment = 'middle' end,
      'objectalignment must be one of Tiled\'s alignments' },
    { 'an unknown tilerendersize', function(m) m.tilesets[1].tilerendersize = 'big' end,
      'tilerendersize must be \'tile\' or \'grid\', got string "big"' },
    { 'an unknown fillmode', function(m) m.tilesets[1].fillmode = 'fill' end,
      'fillmode must be \'stretch\' or \'preserve-aspect-fit\'' },
    { 'tiles not a list', function(m) m.tilesets[1].tiles = true end, 'tiles must be a list, got true' },
    { 'a tile not a table', function(m) m.tilesets[1].tiles[2] = 'x' end, 'tiles[2] must be a table' },
    { 'a tile id twice', function(m) m.tilesets[1].tiles[2] = { id = 1 } end, 'tile id 1 appears twice in its tiles' },
    { 'a tile id that is no whole number', function(m) m.tilesets[1].tiles[1].id = -1 end,
      'tiles[1].id must be a whole number from 0' },
    { 'a gid in an external tileset', function(m)
      m.tilesets[1] = { firstgid = 1, filename = 'ground.tsx', name = 'ext' }
    end, 'layer "ground", tile at column 0, row 0: gid 1 is a tile of tileset "ext", which is in another file'
      .. ' (string "ground.tsx")' },
    { 'a gid beyond every tileset', function(m) m.layers[1].data[3] = 9 end,
      'layer "ground", tile at column 2, row 0: gid 9 is beyond every tileset (tileset "tiles1" has gids 1 to 8)' },
    { 'a gid between two tilesets', function(m)
      m.tilesets[2] = T.tileset(20, 4, {}, { name = 'late' })
      m.layers[1].data[3] = 12
    end, 'gid 12 is beyond every tileset (tileset "tiles1" has gids 1 to 8)' },
    { 'a gid below every tileset', function(m)
      m.tilesets[1].firstgid = 5
      m.layers[1].data[3] = 3
    end, 'tile at column 0, row 0: gid 1 is below every tileset (the first starts at 5)' },
    { 'a gid and no tileset', function(m) m.tilesets = {} end,
      'tile at column 0, row 0: gid 1 names a tile, but the map has no tileset' },
    { 'a negative gid', function(m) m.layers[1].data[2] = -1 end,
      'layer "ground", tile at column 1, row 0: gid must be a whole number from 0 to 4294967295, got -1' },
    { 'a gid of 2^32', function(m) m.layers[1].data[2] = 2 ^ 32 end,
      'gid must be a whole number from 0 to 4294967295' },
    { 'a fractional gid', function(m) m.layers[1].data[4] = 1.5 end, 'tile at column 0, row 1: gid must be a whole' },
    { 'a NaN gid', function(m) m.layers[1].data[4] = nan end, 'got nan' },
    { 'a gid that is a string', function(m) m.layers[1].data[4] = '1' end, 'got string "1"' },
    { 'a hole in the data', function(m) m.layers[1].data[6] = nil end, 'data has 5 gids; a 3 by 2 layer has 6' },
    { 'too many gids', function(m) m.layers[1].data[7] = 1 end, 'data has 7 gids; a 3 by 2 layer has 6' },
    { 'data stored as base64', function(m)
      m.layers[1].data, m.layers[1].encoding, m.layers[1].compression = 'AQAAAA==', 'base64', 'zlib'
    end, 'layer "ground": its tiles are stored as string "base64" compressed with string "zlib"; strike.tiled reads'
      .. ' them as a list of gids: set the map\'s tile layer format to CSV' },
    { 'data not a list', function(m) m.layers[1].data = 4 end, 'layer "ground": data must be a list of gids, got 4' },
    { 'a bad layer width', function(m) m.layers[1].width = -3 end, 'layer "ground": width must be a whole number' },
    { 'chunks not a list', function(m) m.layers[1].chunks = 1 end, 'layer "ground": chunks must be a list, got 1' },
    { 'a chunk not a table', function(m) m.layers[1].chunks = { 1 } end,
      'chunk 1 must be a table {x, y, width, height, data}, got 1' },
    { 'a chunk with a fractional x', function(m)
      m.layers[1].chunks = { { x = 0.5, y = 0, width = 1, height = 1, data = { 1 } } }
    end, 'chunk 1\'s x must be a whole number' },
    { 'a chunk whose data is short', function(m)
      m.layers[1].chunks = { { x = 0, y = 0, width = 2, height = 1, data = { 1 } } }
    end, 'chunk 1\'s data has 1 gids; a 2 by 1 chunk has 2' },
    { 'a chunk in base64', function(m)
      m.layers[1].chunks = { { x = 0, y = 0, width = 2, height = 1, data = 'AQAAAA==' } }
    end, 'chunk 1 stores its tiles as a string (base64)' },
    { 'a chunk whose data is not a list', function(m)
      m.layers[1].chunks = { { x = 0, y = 0, width = 2, height = 1, data = false } }
    end, 'chunk 1\'s data must be a list of gids, got false' },
    { 'overlapping chunks', function(m)
      m.layers[1].chunks = { { x = 0, y = 0, width = 2, height = 2, data = { 1, 1, 1, 1 } },
        { x = 1, y = 1, width = 2, height = 1, data = { 1, 1 } } }
    end, 'layer "ground": chunks 1 and 2 overlap (row 1)' },
    { 'layers not a list', function(m) m.layers[2].layers = 7 end,
      'layer "world": layers must be a list of layers, got 7' },
    { 'a layer not a table', function(m) m.layers[3] = 'x' end, 'map.layers[3] must be a layer table, got string "x"' },
    { 'a layer in a group not a table', function(m) m.layers[2].layers[2] = 1 end,
      'layer "world": layers[2] must be a layer table, got 1' },
    { 'an unknown layer type', function(m) m.layers[1].type = 'terrain' end,
      'layer "ground": type must be \'tilelayer\', \'objectgroup\', \'imagelayer\' or \'group\','
      .. ' got string "terrain"' },
    { 'a NaN layer offset', function(m) m.layers[2].offsetx = nan end,
      'layer "world": offsetx must be a finite number, got nan' },
    { 'a visible that is not a boolean', function(m) m.layers[1].visible = 1 end,
      'layer "ground": visible must be a boolean, got 1' },
    { 'a group holding itself', function(m) m.layers[2].layers[2] = m.layers[2] end,
      'layer "world/world" contains itself' },
    { 'groups nested more than 200 deep', function(m)
      local g = T.group('g', {})
      m.layers[3] = g
      for _ = 1, 201 do
        local inner = T.group('g', {})
        g.layers[1] = inner
        g = inner
      end
    end, 'groups nest more than 200 deep' },
    { 'a collidable image layer', function(m)
      m.layers[3] = { type = 'imagelayer', name = 'sky', image = 'sky.png', properties = { collidable = true } }
    end, 'layer "sky": is an image layer: it has no collision shapes to load' },
    { 'objects not a list', function(m) m.layers[2].layers[1].objects = 'x' end,
      'layer "world/things": objects must be a list, got string "x"' },
    { 'an object not a table', function(m) m.layers[2].layers[1].objects[3] = 4 end,
      'layer "world/things": objects[3] must be an object table, got 4' },
    { 'an unknown shape', function(m) m.layers[2].layers[1].objects[1].shape = 'star' end,
      'layer "world/things", object 1 "door": shape must be one of Tiled\'s (rectangle, ellipse, polygon, polyline,'
      .. ' point, text, capsule), got string "star"' },
    { 'a NaN x', function(m) m.layers[2].layers[1].objects[1].x = nan end,
      'layer "world/things", object 1 "door" (rectangle): x must be a finite number, got nan' },
    { 'an infinite rotation', function(m) m.layers[2].layers[1].objects[1].rotation = -inf end,
      'object 1 "door" (rectangle): rotation must be a finite number, got -inf' },
    { 'a rectangle of width 0', function(m) m.layers[2].layers[1].objects[1].width = 0 end,
      'object 1 "door" (rectangle): width must be a finite number > 0 for a rectangle, got 0' },
    { 'an ellipse of infinite height', function(m)
      local o = m.layers[2].layers[1].objects[1]
      o.shape, o.height = 'ellipse', inf
    end, 'object 1 "door" (ellipse): height must be a finite number > 0 for a ellipse, got inf' },
    { 'a huge rectangle', function(m) m.layers[2].layers[1].objects[1].width = 1e300 end,
      'layer "world/things", object 1 "door" (rectangle): strike.Rectangle:' },
    { 'a rectangle far away', function(m) m.layers[2].layers[1].objects[1].x = 1e300 end,
      'object 1 "door" (rectangle): strike.Rectangle:' },
    { 'a polygon that crosses itself', function(m)
      m.layers[2].layers[1].objects[2].polygon = T.points(0, 0, 10, 10, 10, 0, 0, 10)
    end, 'layer "world/things", object 2 (polygon): strike.Concave: outline intersects itself' },
    { 'a polygon of two points', function(m) m.layers[2].layers[1].objects[2].polygon = T.points(0, 0, 10, 10) end,
      'object 2 (polygon): strike.Concave:' },
    { 'a polygon\'s points not a list', function(m) m.layers[2].layers[1].objects[2].polygon = 5 end,
      'object 2 (polygon): polygon must be a list of points {x =, y =}, got 5' },
    { 'a polygon point not a table', function(m) m.layers[2].layers[1].objects[2].polygon[2] = 5 end,
      'object 2 (polygon): polygon[2] must be a point {x =, y =}, got 5' },
    { 'a polygon point with a NaN', function(m) m.layers[2].layers[1].objects[2].polygon[3].y = nan end,
      'object 2 (polygon): polygon[3].y must be a finite number, got nan' },
    { 'a polyline of one point', function(m)
      local o = m.layers[2].layers[1].objects[2]
      o.shape, o.polygon, o.polyline = 'polyline', nil, T.points(1, 1, 1, 1)
    end, 'object 2 (polyline): strike.Chain: a chain needs at least 2 distinct points, got 1' },
    { 'an instance of a template, as JSON keeps it (only what it changes)', function(m)
      local o = m.layers[2].layers[1].objects[1]
      o.template, o.width, o.height = 'door.tx', nil, nil
    end, 'object 1 "door" (rectangle): is an instance of the template "door.tx", whose shape is in that file;'
      .. ' strike reads no files' },
    { 'an object id twice', function(m) m.layers[2].layers[1].objects[2].id = 1 end,
      'object 1 (polygon): object id 1 is used twice' },
    { 'an object id that is not a number', function(m) m.layers[2].layers[1].objects[2].id = 'two' end,
      'id must be a finite number, got string "two"' },
    { 'a tile object with a negative width', function(m)
      m.layers[2].layers[1].objects[3] = T.object(nil, { id = 9, gid = 1, width = -1, height = 16 })
    end, 'object 9 (tile): width and height must be >= 0 (0: the tile\'s size), got -1 and 16' },
    { 'a tile object of a missing tile', function(m)
      m.layers[2].layers[1].objects[3] = T.object(nil, { id = 9, gid = 100, width = 16, height = 16 })
    end, 'object 9 (tile): gid 100 is beyond every tileset' },
    { 'a tile object whose gid is no number', function(m)
      m.layers[2].layers[1].objects[3] = T.object(nil, { id = 9, gid = true })
    end, 'object 9 (tile): gid must be a whole number from 0 to 4294967295, got true' },
    { 'a tile\'s collision shape that is a tile', function(m)
      m.tilesets[1].tiles[1].objectGroup.objects[1] = T.object(nil, { gid = 1, width = 4, height = 4 })
    end, 'layer "ground", tile at column 1, row 1, collision shape object' },
    { 'a tile\'s collision shape not a table', function(m) m.tilesets[1].tiles[1].objectGroup.objects[2] = 3 end,
      'layer "ground", tile at column 1, row 1: the tile\'s collision shape #2 must be an object table, got 3' },
    { 'a tile\'s collision shapes not an object layer', function(m) m.tilesets[1].tiles[1].objectGroup = 3 end,
      'the tile\'s collision shapes (objectGroup) must be an object layer with a list of objects, got 3' },
    { 'a tile\'s collision polygon that crosses itself', function(m)
      m.tilesets[1].tiles[1].objectGroup.objects[1].polygon = T.points(0, 0, 10, 10, 10, 0, 0, 10)
    end, 'layer "ground", tile at column 1, row 1, collision shape object 3 (polygon): strike.Concave: outline'
      .. ' intersects itself' },
    { 'a property collidable that is a string', function(m) m.layers[1].properties.collidable = 'true' end,
      'layer "ground": property collidable must be a boolean (a bool property in Tiled), got string "true"' },
    { 'a property sensor that is a number', function(m) m.layers[2].layers[1].objects[1].properties.sensor = 1 end,
      'object 1 "door" (rectangle): property sensor must be a boolean' },
    { 'a property layer that is a number', function(m) m.layers[2].properties.layer = 3 end,
      'layer "world": property layer must be a string, got 3' },
    { 'a property mask that is a list', function(m) m.layers[2].properties.mask = { 'a' } end,
      'property mask must be a string, got table' },
    { 'a property group with a fraction', function(m) m.layers[2].properties.group = 1.5 end,
      'property group must be a whole number (an int property in Tiled), got 1.5' },
    { 'a property oneway that is a string', function(m) m.tilesets[1].tiles[1].properties.oneway = 'yes' end,
      'tile at column 1, row 1: property oneway must be a boolean' },
    { 'properties that are not a table', function(m) m.layers[1].properties = 'x' end,
      'layer "ground": properties must be a table, got string "x"' },
    { 'a JSON property without a name', function(m) m.layers[1].properties = { { type = 'bool', value = true } } end,
      'layer "ground": properties[1] must be a property {name =, type =, value =} (as a JSON map has them),'
      .. ' got table' },
    { 'a JSON property of the wrong type', function(m)
      m.layers[1].properties = { { name = 'collidable', type = 'string', value = 'true' } }
    end, 'layer "ground": property collidable must be a boolean' },
  }

  for _, case in ipairs(cases) do
    it(case[1] .. ', with nothing added to the space', function()
      local m = base()
      case[2](m)
      local space = S.pace()
      local mine = space:add(S.trikers.Circle(0, 0, 1))
      expect.raisesAt(function() S.tiled(m, space) end, case[3])
      assert.equals(1, space:count())
      assert.equals(mine, space:bodies()[1])
    end)
  end

  it('the arguments: a map, a space, options', function()
    local space = S.pace()
    expect.raisesAt(function() S.tiled(nil, space) end, 'strike.tiled: argument 1 must be a Tiled map (the table of'
      .. ' Tiled\'s Lua export, or a JSON map decoded into tables), got nil')
    expect.raisesAt(function() S.tiled({}, space) end, 'got a table without a list of layers (layers)')
    expect.raisesAt(function() S.tiled({ layers = {} }, space) end, 'got a table without a tile width (tilewidth)')
    expect.raisesAt(function() S.tiled(S.hapes.Circle(0, 0, 1), space) end, 'argument 1 must be a Tiled map')
    expect.raisesAt(function() S.tiled(base()) end, 'strike.tiled: argument 2 must be a space (S.pace()), got nil')
    expect.raisesAt(function() S.tiled(base(), {}) end, 'argument 2 must be a space (S.pace()), got table')
    expect.raisesAt(function() S.tiled(base(), space, 'walls') end,
      'argument 3 (options) must be a table such as {layers = {\'Walls\'}}, got string "walls"')
    expect.raisesAt(function() S.tiled(base(), space, { layer = { 'x' } }) end,
      'unknown option string "layer" (the option is layers)')
    expect.raisesAt(function() S.tiled(base(), space, { layers = 'ground' }) end,
      'options.layers must be a list of layer names, got string "ground"')
    expect.raisesAt(function() S.tiled(base(), space, { layers = { 'ground', 4 } }) end,
      'options.layers[2] must be a layer name (a string), got 4')
    expect.raisesAt(function() S.tiled(base(), space, { layers = { 'ground', x = 'y' } }) end,
      'options.layers must be a list of layer names, got the key string "x"')
    expect.raisesAt(function() S.tiled(base(), space, { layers = { 'ground', 'Ground' } }) end,
      'strike.tiled: options.layers names "Ground", which is no layer of the map')
    assert.equals(0, space:count())
    -- (the layers it names exist: fine)
    assert.equals(5, #S.tiled(base(), space, { layers = { 'ground', 'world' } }).bodies)
  end)

  it('adding to the space is all or nothing: an error while adding takes back what was added, and goes on as it'
    .. ' was raised', function()
    local space = S.pace()
    local mine = space:add(S.trikers.Circle(0, 0, 1))
    local add, calls = space.add, 0
    local boom = {}
    space.add = function(self, body, opts) -- (the space's own add, failing at the fourth body)
      calls = calls + 1
      if calls == 4 then error(boom) end
      return add(self, body, opts)
    end
    local ok, err = pcall(S.tiled, base(), space)
    assert.is_false(ok)
    assert.equals(boom, err)
    assert.equals(4, calls)
    space.add = nil
    assert.equals(1, space:count())
    assert.equals(mine, space:bodies()[1])
    assert.equals(5, #S.tiled(base(), space).bodies)
  end)

  it('level:remove with \'.\' is an error at the caller\'s line', function()
    local level = S.tiled(base(), S.pace())
    expect.raisesAt(function() level.remove() end, 'strike.tiled: level:remove: called with \'.\' instead of \':\'')
  end)
end)
