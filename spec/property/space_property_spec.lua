-- Property specs for S.pace: on 1,500 seeded random worlds (spec/property/space_world.lua:
-- 1-60 bodies of every kind, scales 1e-3..1e4, offsets up to 1e6), after each batch of random
-- operations (transforms of bodies and nested members, Collider:add/remove of members,
-- space:add/remove/set, setFilter on and off, bodies placed to touch exactly), every query and
-- collisions() are compared with a brute-force oracle that shares no code with strike/space:
-- S.triking, containsPoint and rayCast over every body and pair, the pair rule (layers, masks,
-- groups, the pair filter) and the orders (add order; pairs by ranks; rays by distance, then
-- rank) computed here, and the begin/stay/end events against a model of the touching pairs
-- of the previous call. Reproduce a failure with STRIKE_SEED=<seed> STRIKE_SPACE_WORLD=<world>
-- (any VM): the message names both.
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local budget = require('spec.helpers.budget')
local World = require('spec.property.space_world')

local abs, max, sqrt, cos, sin, pi = math.abs, math.max, math.sqrt, math.cos, math.sin, math.pi
-- (globals as locals: busted runs a spec file in an environment whose lookups cost a call)
local ipairs, pairs, type, tostring, select, error, tonumber = ipairs, pairs, type, tostring, select, error, tonumber
local unpack = table.unpack or unpack -- luacheck: ignore 113 143
local g = World.g

local SEED = PRNG.seedFromEnv(20250612)
local ONLY = tonumber(os.getenv('STRIKE_SPACE_WORLD') or '')

-- Whether two sensors make a pair (reported through events). The contract (issue 11) says a
-- pair with a sensor is reported through events, not whether two sensors make one;
-- strike/space/Space.lua reports them (a pair is a sensor pair when either body is one).
local SENSOR_SENSOR = true

---------------------------------------------------------------------------------------
-- One world: build it, then batches of operations, each followed by the comparisons.

local function runWorld(seed, index, stats, cfg)
  local rng = PRNG.new(seed + 7919 * index)
  local w = World.new(rng, index)
  local space = w.space
  local batch = 0
  local function count(k, v) stats[k] = (stats[k] or 0) + (v or 1) end

  -- (the arguments are described only on failure: bodies by their ids, kinds and ranks,
  -- MTVs by their vectors, fractions at full precision)
  local function fail(fmt, ...)
    local args = { n = select('#', ...), ... }
    for i = 1, args.n do
      local v = args[i]
      if type(v) == 'number' then
        if v % 1 ~= 0 then args[i] = g(v) end
      elseif type(v) == 'table' and w.info[v] then
        args[i] = w:describe(v)
      elseif type(v) == 'table' and type(v.x) == 'number' and type(v.y) == 'number' then
        args[i] = ('(%s, %s)'):format(g(v.x), g(v.y))
      elseif type(v) ~= 'string' then
        args[i] = tostring(v)
      end
    end
    error(('seed %d world %d batch %d (rerun: STRIKE_SEED=%d STRIKE_SPACE_WORLD=%d): %s\n  world: scale %s, centre'
      .. ' (%s, %s), %d bodies; %s'):format(seed, index, batch, seed, index, fmt:format(unpack(args, 1, args.n)),
      g(w.s), g(w.cx), g(w.cy), #w.entries, w:history()), 0)
  end
  local function check(cond, fmt, ...)
    if not cond then fail(fmt, ...) end
  end
  w.fail = fail
  local D = function(body) return w:describe(body) end
  -- lengths: the world's scale plus its distance from the origin
  local span = w.s + abs(w.cx) + abs(w.cy)

  -- the pair filter: called with a added before b, both in the space
  local misuse = {}
  local ops = {}
  ops.pairFilter = function(a, b)
    local ea, eb = w.entryOf[a], w.entryOf[b]
    if not (ea and eb) then
      misuse[#misuse + 1] = ('the pair filter got %s, %s: not both in the space'):format(D(a), D(b))
      return true
    end
    if ea.rank > eb.rank then
      misuse[#misuse + 1] = ('the pair filter got %s before %s'):format(D(a), D(b))
    end
    return w:pairFilterValue(a, b)
  end
  local function noMisuse(what)
    check(#misuse == 0, '%s: %s', what, misuse[1])
  end

  -- can the entries ea, eb (ea added first) collide? (the pair rule, then the pair filter)
  local function allowed(ea, eb)
    if ea.rank > eb.rank then ea, eb = eb, ea end
    return World.ruleAllows(ea, eb) and (not w.pairFilter or w:pairFilterValue(ea.body, eb.body))
  end

  local function mtvMatches(m, e)
    if type(m) ~= 'table' or type(m.x) ~= 'number' or type(m.y) ~= 'number' then return false end
    local L = sqrt(e.x * e.x + e.y * e.y)
    return abs(m.x - e.x) <= 1e-9 * L and abs(m.y - e.y) <= 1e-9 * L
  end

  -- random query filters: nil, a function of the body, or a layer filter; each with the
  -- model's answer for an entry, and a description
  local filterMisuse = {}
  local function randomFilter()
    local r = rng:next()
    if r < 0.4 then return nil, function() return true end, 'no filter' end
    if r < 0.7 then
      local m = rng:int(2, 4)
      local k = rng:int(0, m - 1)
      local function pass(e) return w.info[e.body].id % m ~= k end
      return function(body)
        local e = w.entryOf[body]
        if not e then
          filterMisuse[#filterMisuse + 1] = 'the query filter got a body not in the space: ' .. D(body)
          return false
        end
        return pass(e)
      end, pass, ('function (id %% %d ~= %d)'):format(m, k)
    end
    local list, set = {}, {}
    for _, name in ipairs(w.layers) do
      if rng:next() < 0.4 then
        list[#list + 1] = name
        set[name] = true
      end
    end
    return { mask = list }, function(e) return set[e.layer] == true end, 'mask {' .. table.concat(list, ',') .. '}'
  end
  local function noFilterMisuse(what)
    check(#filterMisuse == 0, '%s: %s', what, filterMisuse[1])
  end

  -- events: callbacks that log a snapshot of what they get (the records are reused)
  local events = cfg.events and rng:next() < cfg.events
  local logged = {}
  local cbs = { begin = {}, stay = {}, ['end'] = {} }
  local function logger(tag)
    return function(a, b, rec)
      local snap = { tag = tag, a = a, b = b, ra = rec and rec.a, rb = rec and rec.b, sensor = rec and rec.sensor }
      if rec and type(rec.mtv) == 'table' then
        snap.mtv = { x = rec.mtv.x, y = rec.mtv.y }
      else
        snap.mtv = rec and rec.mtv
      end
      local c = rec and rec.contacts
      if type(c) == 'table' then
        local copy = { count = c.count }
        for i = 1, c.count or 0 do
          local p = c[i]
          copy[i] = { x = p.x, y = p.y, id = p.id, persisted = p.persisted }
        end
        snap.contacts = copy
      end
      logged[#logged + 1] = snap
    end
  end
  local function on(event, tag)
    local fn = logger(tag)
    check(space:on(event, fn) == fn, 'space:on did not return the callback')
    local list = cbs[event]
    list[#list + 1] = { tag = tag, fn = fn }
  end
  if events then
    on('begin', 'begin1')
    on('stay', 'stay')
    on('end', 'end')
    if rng:next() < 0.5 then on('begin', 'begin2') end
    if rng:next() < 0.3 then on('end', 'end2') end
  end

  -- the touching pairs of the previous collisions() call (the model), in pair order
  local prev, prevKey = {}, {}

  -- every touching pair now, sensor pairs included, in pair order
  local function touching()
    local list, E = {}, w.entries
    for i = 1, #E do
      local ea = E[i]
      for j = i + 1, #E do
        local eb = E[j]
        if (SENSOR_SENSOR or not (ea.sensor and eb.sensor)) and allowed(ea, eb) then
          local m = S.triking(ea.body, eb.body)
          if m then
            list[#list + 1] = { a = ea.body, b = eb.body, key = ea.rank .. ':' .. eb.rank, sensor = ea.sensor or
              eb.sensor, mtv = m }
          elseif w.info[ea.body].exact and w.info[eb.body].exact then
            local ax0, ay0, ax1, ay1 = ea.body:getBounds()
            local bx0, by0, bx1, by1 = eb.body:getBounds()
            if (ax1 == bx0 or bx1 == ax0) and ay0 < by1 and by0 < ay1
              or (ay1 == by0 or by1 == ay0) and ax0 < bx1 and bx0 < ax1 then
              count('exact touches')
            end
          end
        end
      end
    end
    return list
  end

  local collOut = {}
  local function compareCollisions()
    local cur = touching()
    logged = {}
    misuse = {}
    local got, n
    if rng:next() < 0.8 then
      got, n = space:collisions(collOut)
      check(got == collOut, 'collisions(out) returned another table')
    else
      got, n = space:collisions()
    end
    noMisuse('collisions()')
    local k = 0
    for _, p in ipairs(cur) do
      if not p.sensor then
        k = k + 1
        local r = got[k]
        check(k <= n and type(r) == 'table', 'collisions() gives %d pairs; pair %d, %s-%s, is missing', n, k, p.a, p.b)
        check(r.a == p.a and r.b == p.b, 'collisions() pair %d is %s-%s, expected %s-%s', k, r.a, r.b, p.a, p.b)
        check(r.sensor == false, 'collisions() pair %d (%s-%s): sensor is %s', k, p.a, p.b, r.sensor)
        check(mtvMatches(r.mtv, p.mtv), 'collisions() pair %d (%s-%s): mtv %s, S.triking %s', k, p.a, p.b,
          r.mtv, p.mtv)
      end
    end
    if n ~= k then
      local extra = got[k + 1]
      fail('collisions() gives %d pairs, the oracle %d; the first extra: %s', n, k,
        type(extra) == 'table' and (D(extra.a) .. '-' .. D(extra.b)) or tostring(extra))
    end
    count('collisions calls')
    count('colliding pairs', k)
    count('sensor pairs', #cur - k)

    -- events: every 'end' in the previous call's order, then begin/stay in pair order
    local curKey = {}
    for _, p in ipairs(cur) do
      curKey[p.key] = p
      if events and not p.sensor then -- the contacts, and their ids for the next call's persisted flags
        p.ite = S.ite(p.mtv)
        p.points = {}
        for j = 1, p.ite and p.ite.count or 0 do
          local q = p.ite[j]
          p.points[j] = { id = q.id, sa = q.colliderShape or p.mtv.colliderShape,
            sb = q.collidedShape or p.mtv.collidedShape }
        end
      end
    end
    local expected = {}
    local function expect(event, p, before)
      for _, cb in ipairs(cbs[event]) do
        expected[#expected + 1] = { tag = cb.tag, event = event, p = p, before = before }
      end
    end
    for _, p in ipairs(prev) do
      if not curKey[p.key] then expect('end', p) end
    end
    for _, p in ipairs(cur) do
      if prevKey[p.key] then expect('stay', p, prevKey[p.key]) else expect('begin', p) end
    end
    if events then
      for i = 1, max(#expected, #logged) do
        local x, l = expected[i], logged[i]
        check(x and l, 'event %d: expected %s %s-%s, got %s %s-%s', i, x and x.tag or 'none', x and x.p.a or '',
          x and x.p.b or '', l and l.tag or 'none', l and l.a or '', l and l.b or '')
        local p = x.p
        check(l.tag == x.tag and l.a == p.a and l.b == p.b, 'event %d: expected %s %s-%s, got %s %s-%s', i, x.tag,
          p.a, p.b, l.tag, l.a, l.b)
        check(l.ra == p.a and l.rb == p.b, 'event %d (%s %s-%s): the record holds %s-%s', i, x.tag, p.a, p.b,
          l.ra, l.rb)
        if x.event ~= 'end' then
          check(l.sensor == p.sensor, 'event %d (%s %s-%s): record.sensor %s', i, x.tag, p.a, p.b,
            l.sensor)
          if p.sensor then
            check(l.mtv == false, 'event %d (%s %s-%s): a sensor pair with mtv %s', i, x.tag, p.a, p.b,
              l.mtv)
          else
            check(mtvMatches(l.mtv, p.mtv), 'event %d (%s %s-%s): mtv %s, S.triking %s', i, x.tag, p.a, p.b,
              l.mtv, p.mtv)
            -- contacts: S.ite of the MTV; persisted when the previous record had the same id
            local e, c = p.ite, l.contacts
            local ne = e and e.count or 0
            check((c and c.count or 0) == ne, 'event %d (%s %s-%s): %s contacts, S.ite gives %d', i, x.tag, p.a,
              p.b, c and c.count or 'no', ne)
            -- (a point persists when the previous record had one with its id between the same
            -- member shapes: ids are each member pair's own; a point names its shapes in a
            -- compound result, else they are the MTV's)
            local before = x.before and x.before.points or {}
            for j = 1, ne do
              local q, eq = c[j], e[j]
              local tol = 1e-9 * span
              check(q.id == eq.id and abs(q.x - eq.x) <= tol and abs(q.y - eq.y) <= tol,
                'event %d (%s %s-%s): contact %d is %s at (%s, %s), S.ite %s at (%s, %s)', i, x.tag, p.a, p.b, j,
                q.id, q.x, q.y, eq.id, eq.x, eq.y)
              local want, pt = false, p.points[j]
              for _, o in ipairs(before) do
                if o.id == pt.id and o.sa == pt.sa and o.sb == pt.sb then want = true end
              end
              check(q.persisted == want, 'event %d (%s %s-%s): contact %d (id %s) persisted %s, expected %s', i, x.tag,
                p.a, p.b, j, q.id, q.persisted, want)
              if want then count('persisted contacts') end
            end
          end
        end
        count('events ' .. x.event)
      end
    end
    prev, prevKey = cur, curKey

    -- a second call with nothing changed: the same pairs, and only 'stay'
    if events and rng:next() < 0.1 then
      logged = {}
      local _, n2 = space:collisions(collOut)
      check(n2 == n, 'collisions() again: %d pairs, then %d', n, n2)
      local stays = 0
      for _, l in ipairs(logged) do
        check(l.tag == 'stay', 'collisions() again, nothing changed: a %s event for %s-%s', l.tag, l.a, l.b)
        stays = stays + 1
        for j = 1, l.contacts and l.contacts.count or 0 do -- (the same contacts: every point persisted)
          check(l.contacts[j].persisted == true, 'collisions() again: contact %d of %s-%s not persisted', j, l.a, l.b)
        end
      end
      check(stays == #cbs.stay * #cur, 'collisions() again: %d stay events for %d pairs', stays, #cur)
    end
  end

  local function compareBookkeeping()
    local list, n = space:bodies()
    check(space:count() == #w.entries and n == #w.entries, 'count() %d, bodies() %d, the model %d', space:count(), n,
      #w.entries)
    for i, e in ipairs(w.entries) do
      check(list[i] == e.body, 'bodies()[%d] is %s, expected %s', i, list[i], e.body)
    end
    for _, e in ipairs(w.entries) do
      check(space:has(e.body), 'has(%s) is false', e.body)
      -- get: layer, mask (a sorted list of names; nil for every layer), group, sensor
      local layer, mask, group, sensor = space:get(e.body)
      check(layer == e.layer and group == e.group and sensor == e.sensor, 'get(%s) gives %s, %s, %s; the model %s,'
        .. ' %s, %s', e.body, layer, group, sensor, e.layer, e.group, e.sensor)
      check((mask == nil) == (e.mask == false), 'get(%s): mask %s, the model %s', e.body, mask, e.mask)
      if mask then
        local k = 0
        for _ in pairs(e.mask) do k = k + 1 end
        check(#mask == k, 'get(%s): mask of %d names, the model %d', e.body, #mask, k)
        for i, name in ipairs(mask) do
          check(e.mask[name] and (i == 1 or mask[i - 1] < name), 'get(%s): mask[%d] = %s', e.body, i, name)
        end
      end
    end
    for _, body in ipairs(w.pool) do check(not space:has(body), 'has(%s) is true', body) end
  end

  -- check(body [, filter [, out]])
  local checkOut = {}
  local function compareCheck(body, transient)
    local filter, pass, fdesc = randomFilter()
    local ee = w.entryOf[body]
    local exp = {}
    if not (ee and ee.sensor) then
      for _, e in ipairs(w.entries) do
        if e.body ~= body and not e.sensor and pass(e) and (not ee or allowed(ee, e)) then
          local m = S.triking(body, e.body)
          if m then exp[#exp + 1] = { b = e.body, mtv = m } end
        end
      end
    end
    misuse, filterMisuse = {}, {}
    local got, n
    if rng:next() < 0.7 then
      got, n = space:check(body, filter, checkOut)
      check(got == checkOut, 'check(body, filter, out) returned another table')
    else
      got, n = space:check(body, filter)
    end
    local what = ('check(%s%s, %s)'):format(D(body), transient and ' transient' or '', fdesc)
    noMisuse(what)
    noFilterMisuse(what)
    for i = 1, max(n, #exp) do
      local r, x = i <= n and got[i], exp[i]
      check(r and x and r.a == body and r.b == x.b, '%s: %d records, the oracle %d; record %d is %s-%s, the oracle'
        .. ' %s', what, n, #exp, i, r and r.a or 'none', r and r.b or '', x and x.b or 'none')
      check(mtvMatches(r.mtv, x.mtv), '%s: record %d (%s): mtv %s, S.triking %s', what, i, x.b, r.mtv,
        x.mtv)
    end
    count('check calls')
    count('check hits', n)
  end

  -- a list of bodies (queryPoint, queryRect, queryShape) against the model's
  local function compareList(what, got, n, exp)
    for i = 1, max(n, #exp) do
      local b = i <= n and got[i] or 'none'
      check(b == exp[i], '%s: %d bodies, the oracle %d; body %d is %s, the oracle %s', what, n, #exp, i, b,
        exp[i] or 'none')
    end
  end

  local pointOut, rectOut, shapeOut, rayOut = {}, {}, {}, {}

  local function queryPoint()
    local x, y
    local e = w:randomEntry()
    local r = rng:next()
    if e and r < 0.3 then
      x, y = e.body:getCentroid()
    elseif e and r < 0.45 then -- a vertex (on the boundary of its own body)
      local leaf = World.firstLeaf(e.body)
      local k = leaf and leaf:getVertexCount() or 0
      if k > 0 then x, y = leaf:getVertex(rng:int(1, k)) else x, y = w:randomPoint() end
    else
      x, y = w:randomPoint()
      if r > 0.85 then x, y = w:snap(x), w:snap(y) end -- on the exact grid: on the sides of exact bodies
    end
    local filter, pass, fdesc = randomFilter()
    local exp = {}
    for _, f in ipairs(w.entries) do
      if pass(f) and f.body:containsPoint(x, y) then exp[#exp + 1] = f.body end
    end
    filterMisuse = {}
    local got, n = space:queryPoint(x, y, filter, pointOut)
    local what = ('queryPoint(%s, %s, %s)'):format(g(x), g(y), fdesc)
    noFilterMisuse(what)
    check(got == pointOut, '%s: returned another table', what)
    compareList(what, got, n, exp)
    count('queryPoint calls')
    count('queryPoint hits', n)
  end

  local function queryRect()
    local x, y, wd, ht
    local e = w:randomEntry()
    local r = rng:next()
    if e and r < 0.25 then -- a body's own bounding box
      x, y, wd, ht = e.body:getBbox()
      if not (wd > 0 and ht > 0) then x, y, wd, ht = nil, nil, nil, nil end
    elseif r < 0.35 then -- everything
      local L = w:side()
      x, y, wd, ht = w.cx - L, w.cy - L, 2 * L, 2 * L
    end
    if not x then
      x, y = w:randomPoint()
      wd, ht = w.s * World.logRange(rng, 0.05, 10), w.s * World.logRange(rng, 0.05, 10)
      if rng:next() < 0.3 then x, y, wd, ht = w:snap(x), w:snap(y), w.u * rng:int(1, 64), w.u * rng:int(1, 64) end
    end
    -- The rectangle has its corners at its centre -+ half its sides (the space places them
    -- so). A rectangle made at the origin and moved to the centre has those corners when
    -- its own corners came out exactly -+ half its sides (as for dyadic sides, on the exact
    -- grid): then the oracle is exact. Otherwise they may be a rounding off, and a body that
    -- the rectangle shrunk and grown by 1e-12 of the coordinates sort differently may go
    -- either way.
    local hw, hh = wd / 2, ht / 2
    local cx, cy = x + hw, y + hh
    local R = S.hapes.Rectangle(0, 0, wd, ht):translate(cx, cy)
    local x0, y0, x1, y1 = R:getBounds()
    local exact = x0 == cx - hw and x1 == cx + hw and y0 == cy - hh and y1 == cy + hh
    local inner, outer
    if not exact then
      local pad = 1e-12 * (abs(cx) + abs(cy) + wd + ht)
      inner = S.hapes.Rectangle(0, 0, max(wd - 2 * pad, hw), max(ht - 2 * pad, hh)):translate(cx, cy)
      outer = S.hapes.Rectangle(0, 0, wd + 2 * pad, ht + 2 * pad):translate(cx, cy)
    end
    local filter, pass, fdesc = randomFilter()
    local exp, either = {}, {}
    for _, f in ipairs(w.entries) do
      if pass(f) then
        if S.triking(exact and R or inner, f.body) then
          exp[#exp + 1] = f.body
        elseif not exact and S.triking(outer, f.body) then
          exp[#exp + 1] = f.body
          either[f.body] = true
          count('queryRect bodies on the rounded rectangle\'s side')
        end
      end
    end
    filterMisuse = {}
    local got, n = space:queryRect(x, y, wd, ht, filter, rectOut)
    local what = ('queryRect(%s, %s, %s, %s, %s)'):format(g(x), g(y), wd, ht, fdesc)
    noFilterMisuse(what)
    check(got == rectOut, '%s: returned another table', what)
    -- (exp less the bodies on the side that the space left out)
    local j = 1
    for i = 1, n + 1 do
      local b = i <= n and got[i] or nil
      while exp[j] and exp[j] ~= b and either[exp[j]] do j = j + 1 end
      if b or exp[j] then
        check(exp[j] == b, '%s: %d bodies, the oracle %d; body %d is %s, the oracle %s', what, n, #exp, i,
          b or 'none', exp[j] or 'none')
      end
      j = j + 1
    end
    count(exact and 'queryRect exact' or 'queryRect rounded')
    count('queryRect calls')
    count('queryRect hits', n)
  end

  local function queryShape()
    local q, how
    local e = w:randomEntry()
    local r = rng:next()
    if e and r < 0.25 then
      q, how = e.body, 'a body in the space'
    elseif r < 0.35 and #w.pool > 0 then
      q, how = w.pool[rng:int(1, #w.pool)], 'a body out of the space'
    else
      local x, y = w:randomPoint()
      if rng:next() < 0.7 then
        q, how = w:register(w:shape(x, y, w.s * World.logRange(rng, 0.2, 4)), 'transient'), 'a transient shape'
      else
        q, how = w:newBody(x, y), 'a transient body'
      end
    end
    local filter, pass, fdesc = randomFilter()
    local exp = {}
    for _, f in ipairs(w.entries) do
      if f.body ~= q and pass(f) and S.triking(q, f.body) then exp[#exp + 1] = f.body end
    end
    filterMisuse = {}
    local got, n = space:queryShape(q, filter, shapeOut)
    local what = ('queryShape(%s %s, %s)'):format(how, D(q), fdesc)
    noFilterMisuse(what)
    check(got == shapeOut, '%s: returned another table', what)
    compareList(what, got, n, exp)
    count('queryShape calls')
    count('queryShape hits', n)
  end

  -- a random ray: from the region or from far away, random, aimed at a body, or along an
  -- axis (through exact sides and corners); maxDistance nil or random
  local function randomRay()
    local x, y = w:randomPoint()
    local dx, dy
    local e = w:randomEntry()
    local r = rng:next()
    if r < 0.15 then
      local L = w:side() * World.logRange(rng, 2, 1000)
      local a = rng:range(-pi, pi)
      x, y = w.cx + L * cos(a), w.cy + L * sin(a)
    end
    if e and r < 0.6 and (not e.body.getShapeCount or e.body:getShapeCount() > 0) then
      local tx, ty = e.body:getCentroid()
      dx, dy = tx - x, ty - y
    end
    if not dx or (dx == 0 and dy == 0) then
      local a = rng:range(-pi, pi)
      dx, dy = cos(a), sin(a)
    end
    if r > 0.85 then
      x, y = w:snap(x), w:snap(y)
      local k = rng:int(1, 4)
      dx, dy = ({ 1, -1, 0, 0 })[k], ({ 0, 0, 1, -1 })[k]
    end
    local k = World.logRange(rng, 0.01, 100) -- (the direction's length must not matter)
    dx, dy = dx * k, dy * k
    local maxd
    if rng:next() < 0.5 then maxd = rng:range(0, 2) * (w:side() + sqrt((x - w.cx) ^ 2 + (y - w.cy) ^ 2)) end
    return x, y, dx, dy, maxd
  end

  local function rayHits(x, y, dx, dy, maxd, pass)
    local hits = {}
    for _, f in ipairs(w.entries) do
      if pass(f) then
        local t, hx, hy, nx, ny, shape = f.body:rayCast(x, y, dx, dy, maxd)
        if t then
          hits[#hits + 1] = { body = f.body, rank = f.rank, t = t, x = hx, y = hy, nx = nx, ny = ny,
            shape = shape or f.body }
        end
      end
    end
    table.sort(hits, function(p, q)
      if p.t ~= q.t then return p.t < q.t end
      return p.rank < q.rank
    end)
    if hits[2] and hits[2].t == hits[1].t then count('ray ties') end
    return hits
  end

  local function sameHit(what, h, body, t, hx, hy, nx, ny, shape)
    local tol = 1e-9 * max(h.t, w.s)
    check(body == h.body, '%s: hit %s at %s, expected %s at %s', what, body, t, h.body, h.t)
    check(abs(t - h.t) <= 1e-9 * h.t, '%s (%s): distance %s, rayCast %s', what, body, t, h.t)
    local ptol = 1e-9 * (span + h.t)
    check(abs(hx - h.x) <= ptol and abs(hy - h.y) <= ptol, '%s (%s): point (%s, %s), rayCast (%s, %s)', what, body,
      hx, hy, h.x, h.y)
    check(abs(nx - h.nx) <= 1e-9 and abs(ny - h.ny) <= 1e-9, '%s (%s): normal (%s, %s), rayCast (%s, %s)', what,
      body, nx, ny, h.nx, h.ny)
    check(shape == h.shape, '%s (%s): shape %s, rayCast %s', what, body, shape, h.shape)
    return tol
  end

  local function rayCast()
    local x, y, dx, dy, maxd = randomRay()
    local filter, pass, fdesc = randomFilter()
    local hits = rayHits(x, y, dx, dy, maxd, pass)
    filterMisuse = {}
    local body, t, hx, hy, nx, ny, shape = space:rayCast(x, y, dx, dy, maxd, filter)
    local what = ('rayCast(%s, %s, %s, %s, %s, %s)'):format(g(x), g(y), g(dx), g(dy), tostring(maxd), fdesc)
    noFilterMisuse(what)
    if #hits == 0 then
      check(body == nil, '%s: hit %s at %s, the oracle nothing', what, body, t)
    else
      sameHit(what, hits[1], body, t, hx, hy, nx, ny, shape)
      count('rayCast hits')
    end
    count('rayCast calls')
  end

  local function rayCastAll()
    local x, y, dx, dy, maxd = randomRay()
    local filter, pass, fdesc = randomFilter()
    local hits = rayHits(x, y, dx, dy, maxd, pass)
    filterMisuse = {}
    local got, n = space:rayCastAll(x, y, dx, dy, maxd, filter, rayOut)
    local what = ('rayCastAll(%s, %s, %s, %s, %s, %s)'):format(g(x), g(y), g(dx), g(dy), tostring(maxd), fdesc)
    noFilterMisuse(what)
    check(got == rayOut, '%s: returned another table', what)
    for i = 1, max(n, #hits) do
      local h, r = hits[i], i <= n and got[i]
      check(h and r and h.body == r.body, '%s: %d hits, the oracle %d; hit %d is %s at %s, the oracle %s at %s',
        what, n, #hits, i, r and r.body or 'none', r and r.distance or '-', h and h.body or 'none', h and h.t or '-')
    end
    for i, h in ipairs(hits) do
      local r = got[i]
      sameHit(what .. ' record ' .. i, h, r.body, r.distance, r.x, r.y, r.nx, r.ny, r.shape)
    end
    count('rayCastAll calls')
    count('rayCastAll hits', n)
  end

  ---------------------------------------------------------------------------------------
  -- the world's life

  -- most worlds: 1-60 bodies (log-uniform), a few batches of up to 8 operations; some have
  -- 1-30 and live longer, by small steps (pairs kept from call to call, boxes drifting
  -- inside their fat boxes)
  local long = rng:next() < cfg.long
  local n0 = math.floor((long and 30 or 60) ^ rng:next())
  w:populate(n0)
  count('worlds')
  count('bodies added at the start', n0)
  local batches = long and rng:int(8, 16) or rng:int(2, 5)
  if long then count('long-lived worlds') end
  for b = 1, batches do
    batch = b
    local k = long and rng:int(1, 3) or rng:int(1, 8)
    for _ = 1, k do count('op ' .. w:step(ops)) end
    if events and rng:next() < 0.1 then -- off: one callback goes
      local list = (#cbs.begin > 1 and cbs.begin) or (#cbs['end'] > 1 and cbs['end']) or cbs.stay
      local event = list == cbs.stay and 'stay' or (list == cbs.begin and 'begin' or 'end')
      if #list > 0 then
        local cb = table.remove(list)
        space:off(event, cb.fn)
        w:note('off(%s)', cb.tag)
      end
    end
    compareBookkeeping()
    if events or rng:next() < 0.8 then compareCollisions() end
    for _ = 1, (not long or rng:next() < 0.3) and cfg.queries or 0 do
      local e = w:randomEntry()
      if e then compareCheck(e.body) end
      if rng:next() < 0.3 then
        if #w.pool > 0 and rng:next() < 0.5 then
          compareCheck(w.pool[rng:int(1, #w.pool)], true)
        else
          local x, y = w:randomPoint()
          compareCheck(w:register(w:shape(x, y, w.s * World.logRange(rng, 0.2, 3)), 'transient'), true)
        end
      end
      queryPoint()
      queryRect()
      queryShape()
      rayCast()
      rayCastAll()
    end
  end
  count('batches', batches)
  count('bodies at the end', #w.entries)
  -- everything removed: the next call ends every pair
  if events and rng:next() < 0.3 then
    batch = batch + 1
    while #w.entries > 0 do w:remove(w.entries[rng:int(1, #w.entries)].body) end
    compareCollisions()
  end
end

-- LuaJIT: the first JIT_WORLDS worlds run with the compiler on, the others interpreted. The
-- mix of every shape kind, compound and query overflows the compiler's machine-code area
-- (512 KB: "failed to allocate mcode memory" under -jv) about once a world, and each
-- overflow flushes every trace, to be compiled again: the whole run takes 4 times as long
-- as with the compiler off (30 s against 7). The answers are the same either way: what
-- LuaJIT checks here is its own arithmetic and library.
local JIT_WORLDS = 100

local function run(seed, worlds, cfg)
  local stats = {}
  local jit = rawget(_G, 'jit')
  local ok, err = pcall(function()
    for i = 1, worlds do
      if jit and i == JIT_WORLDS + 1 then jit.off() end
      if not ONLY or ONLY == i then runWorld(seed, i, stats, cfg) end
    end
  end)
  if jit then jit.on() end
  if not ok then error(err, 0) end
  return stats
end

local function report(name, stats)
  if os.getenv('STRIKE_SPACE_STATS') then
    local keys = {}
    for k in pairs(stats) do keys[#keys + 1] = k end
    table.sort(keys)
    io.stderr:write(name .. ':\n')
    for _, k in ipairs(keys) do io.stderr:write(('  %-28s %d\n'):format(k, stats[k])) end
  end
end

describe('S.pace properties', function()
  it('collisions(), events and every query agree with brute force over random worlds', function()
    local stats = run(SEED, budget.cases(1500), { events = 0.5, long = 0.2, queries = 1 })
    report('worlds', stats)
    if not ONLY then
      -- guard against a vacuous property
      for _, k in ipairs({ 'colliding pairs', 'sensor pairs', 'events begin', 'events stay', 'events end',
        'persisted contacts', 'exact touches', 'check hits', 'queryPoint hits', 'queryRect hits', 'queryShape hits',
        'rayCast hits', 'rayCastAll hits', 'op touch', 'op member', 'op memberAdd', 'op memberRemove', 'op set',
        'op filter', 'ray ties' }) do
        assert((stats[k] or 0) >= 50 * budget.SHARE, ('seed %d: only %d %s'):format(SEED, stats[k] or 0, k))
      end
    end
  end)
end)
