-- Error messages that name the actual problem, at the caller's line (issue 20's list: a
-- layer filter whose mask is a string, an options table with a metatable, a rectangle too
-- small for the doubles at its position).
local S = require('strike')
local expect = require('spec.helpers.expect')
local raisesAt = expect.raisesAt
local H, T = S.hapes, S.trikers

describe('error messages', function()
  describe('a query filter', function()
    local sp = S.pace()
    sp:add(T.Rectangle(0, 0, 10, 10), { layer = 'wall' })

    it('{mask = "wall"}: the mask must be a list, and the message shows the list to write', function()
      raisesAt(function() sp:queryPoint(0, 0, { mask = 'wall' }) end,
        'strike.Space:queryPoint: argument 3 (filter): mask must be a list of layer names such as {"wall"}, got'
        .. ' string "wall"')
      raisesAt(function() sp:rayCast(0, 0, 1, 0, nil, { mask = 3 }) end,
        'strike.Space:rayCast: argument 6 (filter): mask must be a list of layer names such as {\'wall\'}, got 3')
    end)

    it('a table without mask names its key; an empty one says so', function()
      raisesAt(function() sp:queryRect(0, 0, 1, 1, { layer = 'wall' }) end,
        'strike.Space:queryRect: argument 5 (filter): a layer filter is {mask = {layer names}}, got a table with'
        .. ' the key "layer" and no mask')
      raisesAt(function() sp:queryShape(H.Circle(0, 0, 1), {}) end,
        'strike.Space:queryShape: argument 2 (filter): a layer filter is {mask = {layer names}}, got an empty table')
    end)

    it('a table with a metatable, or a strike object, is named as such', function()
      raisesAt(function() sp:queryPoint(0, 0, setmetatable({ mask = { 'wall' } }, {})) end,
        'strike.Space:queryPoint: argument 3 (filter) must be nil, a function (body) -> boolean or a table {mask'
        .. ' = {layer names}}, got a table with a metatable')
      raisesAt(function() sp:queryPoint(0, 0, H.Circle(0, 0, 1)) end, 'got a shape')
      -- (a list of names that works, for the boundary)
      assert.equals(1, select(2, sp:queryPoint(0, 0, { mask = { 'wall' } })))
    end)
  end)

  describe('an options table', function()
    local sp = S.pace()
    local body = sp:add(T.Rectangle(0, 0, 10, 10))

    it('with a metatable: add, set and move say so', function()
      local opts = setmetatable({ layer = 'wall' }, { __index = {} })
      raisesAt(function() sp:add(T.Circle(0, 0, 1), opts) end,
        "strike.Space:add: argument 2 (options) must be a plain table such as {layer = 'wall'}, got a table with a"
        .. ' metatable')
      raisesAt(function() sp:set(body, opts) end,
        "strike.Space:set: argument 2 (options) must be a plain table such as {layer = 'wall'}, got a table with a"
        .. ' metatable')
      raisesAt(function() sp:move(body, 1, 1, nil, setmetatable({}, {})) end,
        'strike.Space:move: argument 5 (options) must be a plain table such as {slope = math.rad(50), snap = 4,'
        .. ' step = 8}, got a table with a metatable')
      -- a strike object is named as what it is; a plain table works
      raisesAt(function() sp:add(T.Circle(0, 0, 1), H.Circle(0, 0, 1)) end,
        "argument 2 (options) must be a plain table such as {layer = 'wall'}, got a shape")
      sp:set(body, { layer = 'wall' })
      assert.equals('wall', (sp:get(body)))
    end)
  end)

  describe('unknown options', function()
    it('name the same key whatever pairs order is: the least of several', function()
      local sp = S.pace()
      local body = sp:add(T.Rectangle(0, 0, 10, 10))
      -- (tables built in different orders, many keys: pairs order differs between them)
      local a, b = {}, {}
      local names = { 'zeta', 'Layer', 'mass', 'kind', 'tag', 'alpha', 'x', 'y', 'w', 'h' }
      for i = 1, #names do a[names[i]] = true end
      for i = #names, 1, -1 do b[names[i]] = true end
      b[7], a[7] = true, true
      for _, opts in ipairs({ a, b }) do
        raisesAt(function() sp:set(body, opts) end, 'strike.Space:set: unknown option string "Layer" (options are')
        raisesAt(function() sp:move(body, 1, 1, nil, opts) end, 'strike.Space:move: unknown option string "Layer"')
      end
      raisesAt(function() sp:move(body, 1, 1, nil, { [2] = 1, [10] = 1 }) end, 'unknown option 2 (options are')
    end)
  end)

  describe('a rectangle too small for its position', function()
    it('names the size, the position and the spacing of doubles there, not a degenerate outline', function()
      raisesAt(function() H.Rectangle(1e300, 1e300, 1, 1) end,
        'strike.Rectangle: a 1 by 1 rectangle cannot be told from a point at (1e+300, 1e+300): its corners round'
        .. ' to the same coordinates, doubles there being about 2.2e+284 apart')
      raisesAt(function() T.Rectangle(0, 2 ^ 60, 10, 10) end, 'strike.Rectangle: a 10 by 10 rectangle')
    end)

    it('at 2^53, where doubles are 2 apart: width 1 is refused, width 2 is a rectangle', function()
      local x = 2 ^ 53
      raisesAt(function() H.Rectangle(x, 0, 1, 1) end, 'cannot be told from a point')
      local r = H.Rectangle(x, 0, 2, 2)
      local x0, _, x1 = r:getBounds()
      assert.equals(x - 1, x0)
      assert.equals(x, x1) -- (x + 1 rounds to x: the rectangle is as wide as doubles allow)
    end)
  end)
end)
