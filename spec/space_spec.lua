-- S.pace: bodies, moves noticed without update calls, queries, layers, events, sensors,
-- order, errors at the caller's line, and no garbage with `out` tables. Hand-worked cases;
-- spec/property/space_property_spec.lua compares everything with brute force.
local S = require('strike')
local expect = require('spec.helpers.expect')
local alloc = require('spec.helpers.alloc')
local raisesAt, near = expect.raisesAt, expect.near
local H, T = S.hapes, S.trikers

-- The names of a list of bodies (each body gets a `tag`).
local function tags(list, n)
  local t = {}
  for i = 1, n or #list do t[i] = list[i].tag end
  return table.concat(t, ',')
end

local function tagged(body, tag)
  body.tag = tag
  return body
end

-- "a-b" for each record of collisions()/check().
local function pairTags(list, n)
  local t = {}
  for i = 1, n do t[i] = list[i].a.tag .. '-' .. list[i].b.tag end
  return table.concat(t, ',')
end

describe('S.pace', function()
  describe('bodies', function()
    it('adds, counts, lists in add order, removes; a body re-added comes last', function()
      local sp = S.pace()
      local a = tagged(H.Rectangle(0, 0, 10), 'a')
      local b = tagged(T.Collider(H.Circle(50, 0, 5), H.Circle(60, 0, 5)), 'b')
      local c = tagged(T.Capsule(100, 0, 10, 30), 'c')
      assert.equals(a, sp:add(a))
      sp:add(b)
      sp:add(c, { layer = 'x' })
      assert.equals(3, sp:count())
      assert.is_true(sp:has(a))
      assert.is_false(sp:has(H.Circle(0, 0, 1)))
      assert.is_false(sp:has(nil))
      assert.equals('a,b,c', tags((sp:bodies())))
      assert.equals(a, sp:remove(a))
      assert.is_false(sp:has(a))
      assert.equals(2, sp:count())
      sp:add(a)
      local list, n = sp:bodies()
      assert.equals('b,c,a', tags(list, n))
      -- (the removed body's id was reused by the new add: order still follows adds)
      local d = sp:add(tagged(H.Point(0, 0), 'd'))
      sp:remove(b)
      local e = sp:add(tagged(H.Point(1, 0), 'e'))
      assert.equals('c,a,d,e', tags((sp:bodies())))
      assert.is_true(sp:has(d) and sp:has(e))
    end)

    it('get returns the options; set changes only the keys given; mask = false restores every layer', function()
      local sp = S.pace()
      local a = sp:add(H.Rectangle(0, 0, 10))
      local layer, mask, group, sensor = sp:get(a)
      assert.equals('default', layer)
      assert.is_nil(mask)
      assert.equals(0, group)
      assert.is_false(sensor)
      sp:set(a, { layer = 'player', mask = { 'wall', 'enemy', 'wall' } })
      layer, mask, group, sensor = sp:get(a)
      assert.equals('player', layer)
      assert.same({ 'enemy', 'wall' }, mask)
      assert.equals(0, group)
      assert.is_false(sensor)
      sp:set(a, { group = -2, sensor = true })
      layer, mask, group, sensor = sp:get(a)
      assert.equals('player', layer)
      assert.same({ 'enemy', 'wall' }, mask)
      assert.equals(-2, group)
      assert.is_true(sensor)
      sp:set(a, { mask = false })
      assert.is_nil(select(2, sp:get(a)))
    end)

    it('refuses bad bodies and options at the caller\'s line', function()
      local sp, other = S.pace(), S.pace()
      local r = H.Rectangle(0, 0, 10)
      local k = T.Collider(H.Circle(0, 0, 1))
      sp:add(r)
      raisesAt(function() sp:add(nil) end, 'strike.Space:add: argument 1 must be a strike collider or shape, got nil')
      raisesAt(function() sp:add({}) end, 'strike.Space:add: argument 1 must be a strike collider or shape, got table')
      raisesAt(function() sp:add((k:unpack())) end, 'strike.Space:add: argument 1 (a shape) is held by a collider')
      raisesAt(function() sp:add(r) end, 'strike.Space:add: argument 1 is already in this space')
      raisesAt(function() other:add(r) end, 'strike.Space:add: argument 1 is in another space')
      raisesAt(function() sp:add(k, 5) end, 'strike.Space:add: argument 2 (options) must be a table')
      raisesAt(function() sp:add(k, { layers = 'x' }) end, 'strike.Space:add: unknown option string "layers"')
      raisesAt(function() sp:add(k, { layer = 3 }) end,
        'strike.Space:add: layer must be a layer name (a string), got 3')
      raisesAt(function() sp:add(k, { mask = 'wall' }) end, 'strike.Space:add: mask must be a list of layer names')
      raisesAt(function() sp:add(k, { mask = { 'a', 2 } }) end, 'strike.Space:add: mask[2] must be a layer name')
      raisesAt(function() sp:add(k, { mask = { x = 'a' } }) end,
        'strike.Space:add: mask must be a list of layer names, got the key string "x"')
      raisesAt(function() sp:add(k, { group = 1.5 }) end, 'strike.Space:add: group must be an integer')
      raisesAt(function() sp:add(k, { group = 0 / 0 }) end, 'strike.Space:add: group must be an integer')
      raisesAt(function() sp:add(k, { sensor = 1 }) end, 'strike.Space:add: sensor must be a boolean, got 1')
      assert.is_false(sp:has(k)) -- (nothing half-added)
      assert.equals(1, sp:count())
      raisesAt(function() sp:set(k, {}) end, 'strike.Space:set: argument 1 (a collider) is not in this space')
      raisesAt(function() sp:set(r) end, 'strike.Space:set: argument 2 (options) must be a table')
      raisesAt(function() sp:set(r, { sensor = 'yes' }) end, 'strike.Space:set: sensor must be a boolean')
      raisesAt(function() sp:remove(k) end, 'strike.Space:remove: argument 1 (a collider) is not in this space')
      raisesAt(function() sp:get(k) end, 'strike.Space:get: argument 1 (a collider) is not in this space')
      raisesAt(function() sp:bodies(5) end, 'strike.Space:bodies: argument 1 (out) must be a table')
      raisesAt(function() T.Collider(r) end,
        'strike.Collider:add: argument 1 is in a space; remove it from the space first')
    end)

    it('a copy of a body in a space is in no space', function()
      local sp = S.pace()
      local r = sp:add(H.Rectangle(0, 0, 10))
      local k = sp:add(T.Collider(H.Circle(50, 0, 5)))
      assert.is_false(sp:has(r:copy()))
      assert.is_false(sp:has(k:copy()))
      sp:add(r:copy())
      assert.equals(3, sp:count())
    end)
  end)

  describe('moves are noticed without update calls', function()
    local function hits(sp)
      local list, n = sp:collisions()
      return pairTags(list, n)
    end

    it('transforms of a shape, of a collider and of a nested member; members added and removed', function()
      local sp = S.pace()
      local a = sp:add(tagged(H.Rectangle(0, 0, 10), 'a'))
      local inner = T.Collider(H.Circle(200, 0, 5))
      local b = sp:add(tagged(T.Collider(inner), 'b'))
      assert.equals('', hits(sp))
      a:translate(196, 0)
      assert.equals('a-b', hits(sp))
      b:translate(0, 100)
      assert.equals('', hits(sp))
      local member = inner:unpack()
      member:translate(0, -100) -- a nested member alone
      assert.equals('a-b', hits(sp))
      member:translate(0, 100)
      assert.equals('', hits(sp))
      inner:add(H.Rectangle(196, 0, 4)) -- a new member overlapping a
      assert.equals('a-b', hits(sp))
      inner:remove(2)
      assert.equals('', hits(sp))
      a:scale(30) -- now 300 wide, reaching b's circle
      assert.equals('a-b', hits(sp))
      a:scale(1 / 30)
      a:rotate(1)
      assert.equals('', hits(sp))
    end)

    it('bodies far from the origin, and a jump across the world', function()
      local sp = S.pace()
      local a = sp:add(tagged(H.Circle(1e9, -1e9, 1), 'a'))
      local b = sp:add(tagged(H.Rectangle(1e9 + 1.5, -1e9, 2), 'b'))
      assert.equals('a-b', hits(sp))
      a:translateTo(-1e12, 1e12)
      assert.equals('', hits(sp))
      b:translateTo(-1e12 + 1.5, 1e12)
      assert.equals('a-b', hits(sp))
    end)
  end)

  describe('collisions', function()
    it('every colliding pair, in add order, a added before b, MTV as S.triking(a, b); touching is not colliding',
      function()
      local sp = S.pace()
      local c = tagged(H.Circle(14, 0, 5), 'c')
      local r = tagged(H.Rectangle(0, 0, 20), 'r')
      local t = tagged(H.Rectangle(30, 0, 10), 't') -- touches r? no: 25..35 vs -10..10
      local u = tagged(H.Rectangle(20, 0, 20), 'u') -- touches r exactly at x = 10
      sp:add(c)
      sp:add(r)
      sp:add(t)
      sp:add(u)
      local list, n = sp:collisions()
      assert.equals('c-r,c-u,t-u', pairTags(list, n))
      for i = 1, n do
        local want = S.triking(list[i].a, list[i].b)
        near(list[i].mtv.x, want.x)
        near(list[i].mtv.y, want.y)
        assert.is_false(list[i].sensor)
      end
      near(list[1].mtv.x, -1) -- (from c toward r: r lies at -x of c)
    end)

    it('reuses out and its own records; refuses a bad out', function()
      local sp = S.pace()
      sp:add(H.Circle(0, 0, 5))
      sp:add(H.Circle(8, 0, 5))
      local out = { 'stale', 'entries', 'here' }
      local list, n = sp:collisions(out)
      assert.equals(out, list)
      assert.equals(1, n)
      assert.is_nil(out[2])
      local rec = out[1]
      sp:collisions(out)
      assert.equals(rec, out[1])
      raisesAt(function() sp:collisions(7) end, 'strike.Space:collisions: argument 1 (out) must be a table')
      raisesAt(function() sp:collisions(S.MTV()) end, 'strike.Space:collisions: argument 1 (out) must be a table')
    end)
  end)

  describe('layers, masks, groups and the pair filter', function()
    local function scene(optsA, optsB)
      local sp = S.pace()
      local a = sp:add(H.Circle(0, 0, 5), optsA)
      local b = sp:add(H.Circle(8, 0, 5), optsB)
      return sp, a, b
    end
    local function collide(optsA, optsB)
      local sp = scene(optsA, optsB)
      return select(2, sp:collisions()) == 1
    end

    it('each layer must be in the other\'s mask', function()
      assert.is_true(collide(nil, nil))
      assert.is_true(collide({ layer = 'player' }, { layer = 'enemy', mask = { 'player' } }))
      assert.is_false(collide({ layer = 'player' }, { layer = 'enemy', mask = { 'wall' } }))
      assert.is_false(collide({ layer = 'player', mask = { 'wall' } }, { layer = 'enemy' }))
      assert.is_true(collide({ mask = { 'default' } }, nil))
      assert.is_false(collide({ mask = {} }, nil))
    end)

    it('40 layers on any Lua (no bit library)', function()
      local sp = S.pace()
      local names = {}
      for i = 1, 40 do names[i] = 'L' .. i end
      for i = 1, 40 do sp:add(H.Circle(i * 0.1, 0, 5), { layer = names[i], mask = { names[41 - i] } }) end
      local list, n = sp:collisions()
      assert.equals(20, n) -- i with 41 - i only
      for k = 1, n do
        local i = math.floor(list[k].a:getCentroid() * 10 + 0.5)
        local j = math.floor(list[k].b:getCentroid() * 10 + 0.5)
        assert.equals(41, i + j)
      end
    end)

    it('a shared negative group never collides, a shared positive one always (masks aside)', function()
      assert.is_false(collide({ group = -1 }, { group = -1 }))
      assert.is_true(collide({ group = -1 }, { group = -2 }))
      assert.is_true(collide({ group = 3, mask = {} }, { group = 3, mask = {} }))
      assert.is_false(collide({ group = 3, mask = {} }, { group = 4 }))
    end)

    it('setFilter(fn) sees a added before b; setFilter(nil) removes it; set() applies at the next call', function()
      local sp, a, b = scene()
      local seen = {}
      sp:setFilter(function(x, y)
        seen[#seen + 1] = { x, y }
        return false
      end)
      assert.equals(0, select(2, sp:collisions()))
      assert.equals(a, seen[1][1])
      assert.equals(b, seen[1][2])
      sp:setFilter(nil)
      assert.equals(1, select(2, sp:collisions()))
      sp:set(b, { mask = { 'nothing' } })
      assert.equals(0, select(2, sp:collisions()))
      raisesAt(function() sp:setFilter(5) end, 'strike.Space:setFilter: argument 1 must be a function')
    end)
  end)

  describe('events and sensors', function()
    local function recorder(sp)
      local log = {}
      for _, ev in ipairs({ 'begin', 'stay', 'end' }) do
        sp:on(ev, function(a, b, rec)
          assert.equals(a, rec.a)
          assert.equals(b, rec.b)
          log[#log + 1] = ev .. ':' .. a.tag .. '-' .. b.tag
        end)
      end
      return log
    end

    it('begin, stay, end in the documented order; ends are reported for removed and far-moved bodies', function()
      local sp = S.pace()
      local a = sp:add(tagged(H.Circle(0, 0, 5), 'a'))
      local b = sp:add(tagged(H.Circle(8, 0, 5), 'b'))
      local c = sp:add(tagged(H.Circle(-8, 0, 5), 'c'))
      local log = recorder(sp)
      sp:collisions()
      assert.equals('begin:a-b,begin:a-c', table.concat(log, ','))
      for i = #log, 1, -1 do log[i] = nil end
      c:translate(1e6, 0)
      sp:collisions()
      assert.equals('end:a-c,stay:a-b', table.concat(log, ','))
      for i = #log, 1, -1 do log[i] = nil end
      sp:remove(b)
      local d = sp:add(tagged(H.Circle(8, 0, 5), 'd')) -- (takes b's id: still a new pair)
      sp:collisions()
      assert.equals('end:a-b,begin:a-d', table.concat(log, ','))
      for i = #log, 1, -1 do log[i] = nil end
      sp:set(d, { mask = {} })
      sp:collisions()
      assert.equals('end:a-d', table.concat(log, ','))
      assert.is_truthy(a)
    end)

    it('records hold contact points with feature ids; persisted tells old points from new', function()
      local sp = S.pace()
      local floor = sp:add(tagged(H.Rectangle(0, 0, 100, 10), 'floor'))
      local box = sp:add(tagged(H.Rectangle(0, -9, 10, 10), 'box')) -- sinks 1 into the floor
      local recs = {}
      sp:on('begin', function(_, _, rec) recs[#recs + 1] = rec end)
      sp:on('stay', function(_, _, rec) recs[#recs + 1] = rec end)
      sp:collisions()
      local rec = recs[1]
      assert.equals(floor, rec.a)
      assert.equals(2, rec.contacts.count)
      local want = S.ite(S.triking(floor, box))
      for i = 1, 2 do
        assert.equals(want[i].id, rec.contacts[i].id)
        near(rec.contacts[i].x, want[i].x)
        assert.is_false(rec.contacts[i].persisted)
      end
      box:translate(1, 0) -- the same features touch
      sp:collisions()
      assert.equals(rec, recs[2])
      assert.is_true(rec.contacts[1].persisted)
      assert.is_true(rec.contacts[2].persisted)
      local before = {}
      for i = 1, rec.contacts.count do before[rec.contacts[i].id] = true end
      box:rotate(0.3) -- a corner sinks deeper: one point
      sp:collisions()
      assert.equals(1, rec.contacts.count)
      assert.equals(before[rec.contacts[1].id] == true, rec.contacts[1].persisted)
      box:translate(0, -100) -- apart, then back: a new record, nothing persisted
      sp:collisions()
      box:translate(0, 100)
      sp:collisions()
      local last = recs[#recs] -- (a record the space may have pooled and reused: it began again)
      assert.equals(box, last.b)
      assert.equals(1, last.contacts.count) -- (still turned: its corner)
      for i = 1, last.contacts.count do assert.is_false(last.contacts[i].persisted) end
    end)

    it('a sensor reports events without an MTV and is not in collisions() or check()', function()
      local sp = S.pace()
      local zone = sp:add(tagged(H.Rectangle(0, 0, 50), 'zone'), { sensor = true })
      local p = sp:add(tagged(H.Circle(10, 0, 5), 'p'))
      local log = recorder(sp)
      local recs = {}
      sp:on('begin', function(_, _, rec) recs[#recs + 1] = rec end)
      local _, n = sp:collisions()
      assert.equals(0, n)
      assert.equals('begin:zone-p', log[1])
      assert.is_true(recs[1].sensor)
      assert.is_false(recs[1].mtv)
      assert.is_nil(recs[1].contacts)
      assert.equals(0, select(2, sp:check(p)))
      assert.equals(0, select(2, sp:check(zone)))
      assert.equals(zone, (sp:queryShape(p))[1])
      sp:set(zone, { sensor = false })
      assert.equals(1, select(2, sp:collisions()))
    end)

    it('a callback that raises an error leaves the space consistent: the events it stopped run next call', function()
      local sp = S.pace()
      sp:add(tagged(H.Circle(0, 0, 5), 'a'))
      local b = sp:add(tagged(H.Circle(8, 0, 5), 'b'))
      local c = sp:add(tagged(H.Circle(-8, 0, 5), 'c'))
      local fail = true
      local log = {}
      sp:on('begin', function(x, y)
        log[#log + 1] = 'begin:' .. x.tag .. '-' .. y.tag
        if fail then error('game bug') end
      end)
      sp:on('end', function(x, y) log[#log + 1] = 'end:' .. x.tag .. '-' .. y.tag end)
      assert.has_error(function() sp:collisions() end)
      fail = false
      b:translate(100, 0)
      local list, n = sp:collisions()
      -- (a-c's begin, stopped by the error, comes first: every pair that ends began)
      assert.equals('begin:a-b,begin:a-c,end:a-b', table.concat(log, ','))
      assert.equals('a-c', pairTags(list, n))
      sp:remove(c)
      sp:collisions()
      assert.equals('begin:a-b,begin:a-c,end:a-b,end:a-c', table.concat(log, ','))
    end)

    it('on and off check their arguments; off removes one registration', function()
      local sp = S.pace()
      local n = 0
      local fn = function() n = n + 1 end
      assert.equals(fn, sp:on('begin', fn))
      sp:add(H.Circle(0, 0, 5))
      sp:add(H.Circle(1, 0, 5))
      sp:collisions()
      assert.equals(1, n)
      assert.is_true(sp:off('begin', fn))
      assert.is_false(sp:off('begin', fn))
      raisesAt(function() sp:on('start', fn) end,
        "strike.Space:on: argument 1 must be 'begin', 'stay' or 'end', got string \"start\"")
      raisesAt(function() sp:on('end', 'f') end, 'strike.Space:on: argument 2 must be a function')
      raisesAt(function() sp:off(nil, fn) end, "strike.Space:off: argument 1 must be 'begin', 'stay' or 'end'")
    end)
  end)

  describe('queries', function()
    local sp, a, b, c, d
    before_each(function()
      sp = S.pace()
      a = sp:add(tagged(H.Rectangle(0, 0, 20), 'a'), { layer = 'wall' })
      b = sp:add(tagged(H.Circle(15, 0, 10), 'b'), { layer = 'enemy' })
      c = sp:add(tagged(T.Collider(H.Circle(100, 0, 5), H.Circle(120, 0, 5)), 'c'), { layer = 'enemy' })
      d = sp:add(tagged(H.Circle(0, 0, 3), 'd'), { layer = 'wall', sensor = true })
    end)

    it('check: a body in the space (rules apply) or not', function()
      local list, n = sp:check(a)
      assert.equals('a-b', pairTags(list, n))
      near(list[1].mtv.x, S.triking(a, b).x)
      local probe = H.Circle(110, 0, 6)
      list, n = sp:check(probe)
      assert.equals(1, n)
      assert.equals(c, list[1].b)
      assert.equals(0, select(2, sp:check(probe, { mask = { 'wall' } })))
      assert.equals(1, select(2, sp:check(a, function(o) return o == b end)))
      sp:set(b, { mask = { 'enemy' } })
      assert.equals(0, select(2, sp:check(a)))
    end)

    it('queryPoint, queryRect, queryShape: exact shapes, sensors included, add order', function()
      assert.equals('a,d', tags((sp:queryPoint(1, 0))))
      assert.equals('b', tags((sp:queryPoint(24, 0))))
      assert.equals('', tags((sp:queryPoint(10.5, 9.5)))) -- in b's box, outside the circle... and a's
      assert.equals('c', tags((sp:queryRect(102, -1, 2, 2))))
      assert.equals('', tags((sp:queryRect(106, -1, 8, 2)))) -- between c's circles
      assert.equals('', tags((sp:queryRect(125, 0, 5, 5)))) -- touches c's second circle only at (125, 0)
      assert.equals('a,d', tags((sp:queryRect(-1, -1, 2, 2))))
      assert.equals('a,b', tags((sp:queryRect(4, -1, 2, 2))))
      assert.equals('a', tags((sp:queryRect(4, -1, 2, 2, { mask = { 'wall' } }))))
      assert.equals('a,d', tags((sp:queryShape(H.Circle(0, 0, 1)))))
      assert.equals('b,d', tags((sp:queryShape(a)))) -- (a itself skipped)
      assert.equals('b', tags((sp:queryShape(a, function(o) return o ~= d end))))
    end)

    it('rayCast: the closest hit, ties to the body added first; maxDistance; filters; nil on a miss', function()
      local body, t, x, y, nx, ny, shape = sp:rayCast(-50, 0, 1, 0)
      assert.equals(a, body)
      near(t, 40)
      near(x, -10)
      near(y, 0)
      near(nx, -1)
      near(ny, 0)
      assert.equals(a, shape)
      body, t = sp:rayCast(-50, 0, 2, 0, nil, { mask = { 'enemy' } }) -- (dx, dy) need not be unit
      assert.equals(b, body)
      near(t, 55)
      assert.is_nil(sp:rayCast(-50, 0, 1, 0, 39))
      assert.is_nil(sp:rayCast(-50, 50, 1, 0))
      local _
      body, t, _, _, _, _, shape = sp:rayCast(200, 0, -1, 0)
      assert.equals(c, body)
      near(t, 75)
      assert.equals(select(2, c:unpack()), shape)
      -- a tie: two equal boxes at the same place, the first added wins
      local sp2 = S.pace()
      local first = sp2:add(H.Rectangle(0, 0, 10))
      sp2:add(H.Rectangle(0, 0, 10))
      assert.equals(first, (sp2:rayCast(-20, 0, 1, 0)))
    end)

    it('rayCastAll: every body once, at its first crossing, by distance', function()
      local list, n = sp:rayCastAll(-50, 0, 1, 0)
      assert.equals(4, n)
      assert.equals('a,d,b,c', tags({ list[1].body, list[2].body, list[3].body, list[4].body }))
      near(list[1].distance, 40)
      near(list[2].distance, 47)
      near(list[3].distance, 55)
      near(list[4].distance, 145)
      assert.equals((c:unpack()), list[4].shape)
      local again, k = sp:rayCastAll(-50, 0, 1, 0, 50, { mask = { 'wall' } }, list)
      assert.equals(list, again)
      assert.equals(2, k)
      assert.is_nil(list[3])
    end)

    it('refuses bad queries at the caller\'s line', function()
      raisesAt(function() sp:queryPoint(0 / 0, 0) end, 'strike.Space:queryPoint: x must be a finite number, got nan')
      raisesAt(function() sp:queryPoint(0, 'y') end, 'strike.Space:queryPoint: y must be a finite number')
      raisesAt(function() sp:queryPoint(0, 0, 5) end,
        'strike.Space:queryPoint: argument 3 (filter) must be nil, a function')
      raisesAt(function() sp:queryPoint(0, 0, { mask = { 1 } }) end,
        'strike.Space:queryPoint: argument 3 (filter): mask[1] must be a layer name')
      raisesAt(function() sp:queryPoint(0, 0, nil, 'out') end,
        'strike.Space:queryPoint: argument 4 (out) must be a table')
      raisesAt(function() sp:queryRect(0, 0, 0, 5) end, 'strike.Space:queryRect: w and h must be numbers from')
      raisesAt(function() sp:queryRect(0, 0, 5, -1) end, 'strike.Space:queryRect: w and h must be numbers from')
      raisesAt(function() sp:queryRect(1e308, 1e308, 1e100, 5) end,
        'strike.Space:queryRect: the rectangle is too far out')
      raisesAt(function() sp:queryShape({}) end,
        'strike.Space:queryShape: argument 1 must be a strike collider or shape')
      raisesAt(function() sp:check(5) end, 'strike.Space:check: argument 1 must be a strike collider or shape, got 5')
      raisesAt(function() sp:check(a, nil, 5) end, 'strike.Space:check: argument 3 (out) must be a table')
      raisesAt(function() sp:rayCast(0, 0, 0, 0) end, 'strike.Space:rayCast: the direction (dx, dy) must not be (0, 0)')
      raisesAt(function() sp:rayCast(0, 0, 1 / 0, 0) end, 'strike.Space:rayCast: dx must be a finite number, got inf')
      raisesAt(function() sp:rayCast(0, 0, 1, 0, -1) end,
        'strike.Space:rayCast: maxDistance must be a number >= 0 or nil, got -1')
      raisesAt(function() sp:rayCast(0, 0, 1, 0, nil, true) end,
        'strike.Space:rayCast: argument 6 (filter) must be nil')
      raisesAt(function() sp:rayCastAll(0, 0, 1, 0, nil, nil, 1) end,
        'strike.Space:rayCastAll: argument 7 (out) must be a table')
    end)
  end)

  -- A filter may query the space it filters for: every query keeps its own candidates, ray
  -- and rectangle (Space.lua: enter), so the outer one answers as if nothing ran inside it.
  describe('a filter that queries the same space', function()
    local sp, bodies
    before_each(function()
      sp = S.pace()
      bodies = {}
      for i = 1, 12 do
        local x = (i - 1) * 9
        local body = i % 3 == 0 and H.Rectangle(x, 0, 10, 8) or (i % 3 == 1 and T.Circle(x, 0, 5)
          or T.RegularPolygon(x, 0, 6, 5))
        bodies[i] = sp:add(tagged(body, 'b' .. i))
      end
    end)

    -- Every query there is, each from a filter of the others, at the positions of the bodies.
    local function everyQuery()
      for i = 1, #bodies, 4 do
        local x = (i - 1) * 9
        sp:queryPoint(x, 0)
        sp:queryRect(x - 3, -3, 6, 6)
        sp:queryShape(H.Circle(x, 2, 4))
        sp:check(bodies[i])
        sp:rayCast(x - 20, 1, 1, 0, 40)
        sp:rayCastAll(x - 20, -1, 1, 0, 40)
      end
    end
    local function even(body) return tonumber(body.tag:sub(2)) % 2 == 0 end
    local function nesting(body)
      everyQuery()
      return even(body)
    end

    local function answers(filter)
      local t = {}
      t[#t + 1] = tags(sp:queryPoint(27, 0, filter))
      t[#t + 1] = tags(sp:queryRect(-5, -5, 60, 10, filter))
      t[#t + 1] = tags(sp:queryShape(H.Rectangle(40, 0, 50, 4), filter))
      local list, n = sp:check(bodies[5], filter)
      t[#t + 1] = pairTags(list, n)
      local hit, d = sp:rayCast(-30, 0.5, 1, 0, 200, filter)
      t[#t + 1] = hit.tag .. ('@%.12g'):format(d)
      local hits, k = sp:rayCastAll(-30, -0.5, 1, 0, 200, filter)
      for j = 1, k do t[#t + 1] = hits[j].body.tag .. ('@%.12g'):format(hits[j].distance) end
      return table.concat(t, ' | ')
    end

    it('every query answers as with the same filter that does not nest', function()
      local plain = answers(even)
      assert.is_true(#plain > 40) -- (every query found something)
      assert.equals(plain, answers(nesting))
      -- and queries nested two deep
      assert.equals(plain, answers(function(body)
        sp:queryPoint(0, 0, nesting)
        sp:rayCast(-30, 0, 1, 0, 200, nesting)
        return even(body)
      end))
    end)

    it('a filter that raised an error leaves the space answering as before', function()
      local plain = answers(even)
      for _ = 1, 3 do
        assert.has_error(function() sp:rayCast(-30, 0.5, 1, 0, 200, function() error('boom') end) end)
        assert.has_error(function() sp:queryRect(-5, -5, 60, 10, function() error('boom') end) end)
      end
      assert.equals(plain, answers(even))
      assert.equals(plain, answers(nesting))
    end)

    it('a filter that removes bodies: the query goes on without them, and the space stays whole', function()
      local removed = {}
      local _, n = sp:queryRect(-5, -5, 200, 10, function(body)
        if body == bodies[1] then
          for i = 2, 12, 2 do
            sp:remove(bodies[i])
            removed[bodies[i]] = true
          end
        end
        return true
      end)
      assert.equals(6, n) -- the odd ones: body 1, which removed the others, and 3, 5, ..., 11
      assert.equals(6, sp:count())
      local list, k = sp:queryRect(-5, -5, 200, 10)
      assert.equals(6, k)
      for i = 1, k do assert.is_nil(removed[list[i]]) end
    end)
  end)

  describe('regressions found by the property spec', function()
    it('a ray aimed at a Point hits it (a box of no size survives the slab test\'s rounding)', function()
      local p = H.Point(-8.4000643149018579, 0.11905944446058037)
      local sp = S.pace()
      sp:add(p)
      local x, y = 1.0320830489658217, 6.2198039685468203
      local dx, dy = -8.4000643149018579 - x, 0.11905944446058037 - y
      local want = p:rayCast(x, y, dx, dy)
      assert.is_number(want)
      local body, d = sp:rayCast(x, y, dx, dy)
      assert.equals(p, body)
      assert.equals(want, d)
    end)

    it('a collider hit through the space is the collider\'s own rayCast, to the last bit', function()
      local c = T.Collider(H.Point(-0.55479071594532137, -4.3675628930179231))
      local sp = S.pace()
      sp:add(c)
      local x, y, dx, dy = -5.6295429522309188, 4.2716018549500046, 5.0747522362855975, -8.6391647479679285
      local want = { c:rayCast(x, y, dx, dy) }
      assert.is_number(want[1])
      local got = { sp:rayCast(x, y, dx, dy) }
      assert.equals(c, got[1])
      for i = 1, 6 do assert.equals(want[i], got[i + 1]) end
    end)

    it('an exact tie goes to the body added first, even where the box entry rounds past the hit', function()
      local sp = S.pace()
      local a = sp:add(H.Rectangle(-32, -58880, 128, 192))
      sp:add(H.Rectangle(-32, -58880, 128, 192))
      assert.equals(a, (sp:rayCast(-82.09542654551251, -59525.306431321012, 680.42253359532197, 8764.8926703096677)))
    end)

    it('a body removed and added again before collisions() ends its pairs and begins new ones', function()
      local sp = S.pace()
      local a = sp:add(tagged(H.Circle(0, 0, 5), 'a'))
      local b = sp:add(tagged(H.Circle(8, 0, 5), 'b'))
      local log = {}
      for _, ev in ipairs({ 'begin', 'stay', 'end' }) do
        sp:on(ev, function(x, y) log[#log + 1] = ev .. ':' .. x.tag .. '-' .. y.tag end)
      end
      sp:collisions()
      sp:remove(b)
      sp:add(b) -- (takes its old id back, and comes after a again)
      sp:collisions()
      assert.equals('begin:a-b,end:a-b,begin:a-b', table.concat(log, ','))
      assert.is_truthy(a)
    end)

    it('persisted compares the shapes too, when a body changes between one member and several', function()
      local sp = S.pace()
      local floor = sp:add(T.Collider(H.Rectangle(0, 0, 100, 10)))
      local box = sp:add(H.Rectangle(0, -9, 10, 10))
      local rec
      sp:on('begin', function(_, _, r) rec = r end)
      sp:on('stay', function(_, _, r) rec = r end)
      sp:collisions()
      floor:add(H.Rectangle(500, 0, 10, 2)) -- a member far away: the same contact
      sp:collisions()
      assert.equals(2, rec.contacts.count)
      assert.is_true(rec.contacts[1].persisted)
      assert.is_true(rec.contacts[2].persisted)
      floor:remove(1) -- the floor's piece goes: the box now rests on the other member
      box:translateTo(500, -5.5)
      sp:collisions()
      assert.is_true(rec.contacts.count >= 1)
      for i = 1, rec.contacts.count do assert.is_false(rec.contacts[i].persisted) end
    end)
  end)

  describe('one out table passed to check and rayCastAll in turn', function()
    it('keeps their records apart: check always gives MTVs, rayCastAll distances', function()
      local sp = S.pace()
      local a = sp:add(H.Rectangle(0, 0, 10))
      sp:add(H.Circle(6, 0, 3))
      sp:add(H.Circle(-6, 0, 3))
      local out = {}
      assert.equals(3, select(2, sp:rayCastAll(-50, 0, 1, 0, nil, nil, out)))
      assert.equals(1, select(2, sp:rayCastAll(-50, 0, 1, 0, 42, nil, out))) -- (two hits to the spares)
      local list, n = sp:check(a, nil, out)
      assert.equals(2, n)
      for i = 1, n do near(list[i].mtv.depth, S.triking(a, list[i].b).depth) end
      list, n = sp:rayCastAll(-50, 0, 1, 0, nil, nil, out)
      assert.equals(3, n)
      near(list[1].distance, 41)
    end)
  end)

  describe('allocation with out tables', function()
    setup(alloc.jitOff) -- measured interpreted on LuaJIT: see spec/helpers/alloc.lua
    teardown(alloc.jitOn)

    it('moves + collisions (with events), check, the queries and the rays allocate nothing', function()
      local sp = S.pace()
      local bodies = {}
      for i = 1, 40 do
        local x, y = (i % 8) * 9, math.floor(i / 8) * 9
        local body = i % 3 == 0 and H.Circle(x, y, 5) or (i % 3 == 1 and H.Rectangle(x, y, 10, 8))
          or T.Collider(H.Circle(x, y, 4), H.Rectangle(x + 3, y, 4))
        bodies[i] = sp:add(body, { sensor = i % 7 == 0, layer = i % 2 == 0 and 'even' or 'odd' })
      end
      local calls = 0
      sp:on('begin', function() calls = calls + 1 end)
      sp:on('stay', function() calls = calls + 1 end)
      sp:on('end', function() calls = calls + 1 end)
      local out, checkOut, qOut, rOut = {}, {}, {}, {}
      local t = 0
      local filterT = { mask = { 'even' } }
      local function step()
        t = t + 1
        local s = (t % 2 == 0) and 1 or -1
        for i = 1, 40 do bodies[i]:translate(s * 0.5, 0) end
        sp:collisions(out)
        sp:check(bodies[5], nil, checkOut)
        sp:queryPoint(20, 10, filterT, qOut)
        sp:queryRect(0, 0, 30, 20, nil, qOut)
        sp:queryShape(bodies[3], nil, qOut)
        sp:rayCast(-10, 5, 1, 0.1)
        sp:rayCastAll(-10, 5, 1, 0.1, 200, filterT, rOut)
      end
      -- (1,000 frames: one allocation per frame would be at least 16 KB)
      local kb = alloc.kbPer(step, 1000, 200)
      assert(kb < alloc.ONE_TIME_KB, ('a space frame allocated %.3f KB over 1,000 frames'):format(kb))
      assert.is_true(calls > 0)
      assert.is_true(select(2, sp:collisions(out)) > 0)
    end)

    it('queries run from a filter of another query allocate nothing either', function()
      local sp = S.pace()
      for i = 1, 30 do sp:add(H.Circle((i % 6) * 9, math.floor(i / 6) * 9, 5)) end
      local inner, outer, rOut = {}, {}, {}
      local seen = 0
      local function nested(body)
        sp:queryPoint(9, 9, nil, inner)
        sp:queryRect(0, 0, 20, 20, nil, inner)
        sp:rayCast(-10, 9, 1, 0)
        sp:rayCastAll(-10, 18, 1, 0, 100, nil, rOut)
        seen = seen + 1
        return body ~= nil
      end
      local function step()
        sp:queryRect(0, 0, 30, 30, nested, outer)
        sp:rayCast(-10, 0, 1, 0, 100, nested)
      end
      local kb = alloc.kbPer(step, 1000, 200)
      assert(kb < alloc.ONE_TIME_KB, ('nested queries allocated %.3f KB over 1,000 calls'):format(kb))
      assert.is_true(seen > 1000)
    end)
  end)
end)
