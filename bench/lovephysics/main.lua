--- Box2D, through LÖVE's love.physics, on bench/space.lua's workloads (the same seeded
--- worlds: bench/spaceworld.lua, loaded from the repository root, which must be the current
--- folder). bench/space.lua runs it when `love` is on the PATH:
---   love bench/lovephysics --section frame --n 1000,5000 --frames 60
---   love bench/lovephysics --section rays --rays 10000 --n 1000 --len 300
---   love bench/lovephysics --section build --n 20000
--- and reads the lines it prints, one result each, `box2d <section> key=value ...` (rays:
--- also one `box2d rayhit <ray> <body> <distance>` per ray that hits). No window.
--- bench/narrow.lua runs the narrow section (described at narrow() below):
---   love bench/lovephysics --section narrow --pairs 10000 --seed 42 --workloads poly-poly,circle-poly
---
--- The world: zero gravity, sleeping off (a body moved with setPosition would otherwise stay
--- asleep and its contacts would not be updated), one dynamic body per body of the world,
--- each with one sensor fixture (so that nothing is solved, only detected): the box as
--- newRectangleShape, the polygon as newPolygonShape of bench/spaceworld.lua's vertices, the
--- circle as newCircleShape. LÖVE's default scale (30 px to the metre).
--- A frame: bench/spaceworld.lua's step, setPosition on every body, world:update(1/60), then
--- world:getContacts() and the count of those whose isTouching() is true (Box2D keeps a contact
--- for every pair whose fattened boxes overlap). Box2D's sensor test counts a polygon's skin
--- (0.01 m, 0.3 px) as part of it, and Box2D computes in single precision.
--- Times are os.clock() (processor time), as in bench/space.lua; KB per frame is the Lua
--- heap only (Box2D's own allocations are not visible from Lua).
package.path = './?.lua;' .. package.path
local SW = require('bench.spaceworld')
local W = require('bench.workloads')
local H = require('bench.harness')

local P = love.physics
local clock = os.clock
local jit = rawget(_G, 'jit')

local opts = { section = 'frame', n = { 1000 }, frames = 60, rays = 10000, len = 300, pairs = 10000, seed = 42,
  workloads = { 'poly-poly', 'circle-poly' } }

local function parse(args)
  local i = 1
  while args[i] do
    local a, v = args[i], args[i + 1]
    if a == '--section' then opts.section = v; i = i + 1
    elseif a == '--n' then
      opts.n = {}
      for s in v:gmatch('[^,]+') do opts.n[#opts.n + 1] = tonumber(s) end
      i = i + 1
    elseif a == '--frames' then opts.frames = tonumber(v); i = i + 1
    elseif a == '--rays' then opts.rays = tonumber(v); i = i + 1
    elseif a == '--len' then opts.len = tonumber(v); i = i + 1
    elseif a == '--pairs' then opts.pairs = tonumber(v); i = i + 1
    elseif a == '--seed' then opts.seed = tonumber(v); i = i + 1
    elseif a == '--workloads' then
      opts.workloads = {}
      for w in v:gmatch('[^,]+') do opts.workloads[#opts.workloads + 1] = w end
      i = i + 1
    end
    i = i + 1
  end
end

-- LuaJIT trace flushes and aborts (counted while `counting`).
local flushes, aborts, counting = 0, 0, false
if jit and jit.attach then
  jit.attach(function(what)
    if counting then
      if what == 'flush' then flushes = flushes + 1 elseif what == 'abort' then aborts = aborts + 1 end
    end
  end, 'trace')
end

local function out(line)
  io.stdout:write(line, '\n')
  io.stdout:flush()
end

local function makeBody(world, w, i)
  local b = P.newBody(world, w.x[i], w.y[i], 'dynamic')
  local k, shape = w.kind[i]
  if k == SW.BOX then shape = P.newRectangleShape(w.w[i], w.h[i])
  elseif k == SW.POLYGON then shape = P.newPolygonShape(SW.vertices(w, i, 0, 0))
  else shape = P.newCircleShape(w.r[i]) end
  local f = P.newFixture(b, shape)
  f:setSensor(true)
  f:setUserData(i)
  return b
end

local function build(w)
  local world = P.newWorld(0, 0, false)
  local bodies = {}
  for i = 1, w.n do bodies[i] = makeBody(world, w, i) end
  return world, bodies
end

local function frame(world, bodies, w)
  SW.step(w)
  local x, y = w.x, w.y
  for i = 1, w.n do bodies[i]:setPosition(x[i], y[i]) end
  world:update(1 / 60)
  local contacts = world:getContacts()
  local count = 0
  for j = 1, #contacts do
    if contacts[j]:isTouching() then count = count + 1 end
  end
  return count
end

local function frames(n)
  local w = SW.world(n, SW.seed(n))
  collectgarbage('collect')
  local t0 = clock()
  local world, bodies = build(w)
  local buildMs = (clock() - t0) * 1000
  if jit then jit.flush() end
  local timed, warm = SW.frames(opts.frames, n)
  for _ = 1, warm do frame(world, bodies, w) end
  collectgarbage('collect')
  local times, count = {}, 0
  flushes, aborts, counting = 0, 0, true
  for f = 1, timed do
    local f0 = clock()
    count = frame(world, bodies, w)
    times[f] = (clock() - f0) * 1000
  end
  counting = false
  local fl, ab = flushes, aborts
  -- Lua heap allocated per frame: the second and third of three frames with the GC stopped.
  collectgarbage('collect')
  collectgarbage('stop')
  frame(world, bodies, w)
  local kb0 = collectgarbage('count')
  frame(world, bodies, w)
  frame(world, bodies, w)
  local kb = (collectgarbage('count') - kb0) / 2
  collectgarbage('restart')
  local med, min = SW.medianMin(times)
  out(('box2d frame n=%d frames=%d warm=%d median=%.5f min=%.5f kb=%.4f pairs=%d flushes=%d aborts=%d build=%.3f')
    :format(n, timed, warm, med, min, kb, count, fl, ab, buildMs))
  world:destroy()
end

local function rays(n)
  local w = SW.world(n, SW.seed(n))
  local world = build(w)
  local r = SW.rays(opts.rays, w.side, SW.seed(n) + 1)
  local len = opts.len
  local best, bestF
  local function cb(fixture, _, _, _, _, fraction)
    best, bestF = fixture:getUserData(), fraction
    return fraction -- clip the ray there: what is reported later is closer
  end
  local ox, oy, dx, dy = r.ox, r.oy, r.dx, r.dy
  local hitI, hitD = {}, {}
  local function pass(record)
    for k = 1, r.count do
      best = nil
      local x, y = ox[k], oy[k]
      world:rayCast(x, y, x + dx[k] * len, y + dy[k] * len, cb)
      if record and best then hitI[k], hitD[k] = best, bestF * len end
    end
  end
  pass(true) -- (warm-up, and the answers)
  local bestT = math.huge
  for _ = 1, 3 do
    local t0 = clock()
    pass(false)
    bestT = math.min(bestT, clock() - t0)
  end
  for k = 1, r.count do
    if hitI[k] then out(('box2d rayhit %d %d %.17g'):format(k, hitI[k], hitD[k])) end
  end
  out(('box2d rays n=%d rays=%d rate=%.1f'):format(n, r.count, r.count / bestT))
  world:destroy()
end

-- Build: a new world and N bodies with their fixtures (best of 3).
local function buildTime(n)
  local w = SW.world(n, SW.seed(n))
  local bestT = math.huge
  for _ = 1, 3 do
    collectgarbage('collect')
    local t0 = clock()
    local world = build(w)
    bestT = math.min(bestT, clock() - t0)
    world:destroy()
  end
  out(('box2d build n=%d ms=%.3f'):format(n, bestT * 1000))
end

-- Narrow phase: bench/run.lua's pair workloads (bench/workloads.lua: the same seeded pairs,
-- half of them overlapping, every pair's bounding boxes overlapping), strike's pair tests
-- beside Box2D's contact update, both timed in this process (os.clock).
--
-- strike: S.AT and S.triking over the pairs as bench/run.lua times them (bench/harness.lua's
-- timeRow: best of 5 runs of about 0.1 s; the adapter bench/adapters/strike.lua; verdicts and
-- MTV lengths checked against the workload's oracle first), on all the pairs, on the
-- overlapping ones (hits) and on the others that Box2D finds apart too (clear, below).
--
-- Box2D has no narrow-phase call in love.physics: its narrow phase runs when a world steps.
-- LÖVE 11.4's Box2D 2.3.0 step (b2World::Step) updates every contact of awake bodies
-- (b2ContactManager::Collide: the two fixtures' fat boxes tested, then b2Contact::Update: the
-- manifold, b2CollidePolygons or b2CollidePolygonAndCircle, its points matched to the last
-- step's), then solves the touching contacts, island by island. So: a world is built of the
-- pairs laid out on a grid (W.layout), each pair's two shapes where the workload has them
-- relative to each other and far from every other pair's, so that Box2D's contacts are
-- exactly the pairs. The shapes are fixtures of dynamic bodies at the origin, each fixture
-- placed and turned in its body's frame: pairs 1-100 on the first two bodies (the first
-- shapes on one, the second shapes on the other), 101-200 on the next two, and so on. Zero
-- gravity, sleeping off, LÖVE's 30 px to the metre. A second world holds the same bodies and
-- shapes with each pair's second shape moved clear of its first (W.layout's apart): no
-- contact at all. Both step with world:update(1/60, 0, 0): no velocity or position
-- iteration, so nothing moves (the contact solver is set up, with no impulse to apply),
-- every step meets the same contacts, and the two worlds' steps differ by what the contacts
-- cost. Box2D's time per pair = (a step of the first world - a step of the second) / pairs,
-- each the best of NARROW_ROUNDS samples of about NARROW_SAMPLE seconds, the two worlds in
-- turn.
--
-- What that time holds besides the manifold: for every contact, the loop's fat-box test,
-- b2Contact::Update's bookkeeping (the old manifold copied, the contact ids matched, LÖVE's
-- listener's PreSolve called for a touching contact: it does nothing without callbacks) and
-- two passes of the continuous-collision loop over the contacts (each skips it at once: the
-- bodies are dynamic, none a bullet); for a touching contact, also its place in an island and
-- the contact solver's setup (velocity and position constraints, the warm start with zero
-- impulses, the impulses stored, PostSolve reported). The touching contacts make one island of
-- each pair of bodies where the clear world has two: 100 islands fewer for 10,000 pairs, left
-- in. Variants, each a pair of worlds:
--   solid, all      the workload as it is: Box2D's rate with the solver's setup counted, a
--                   lower bound on its narrow phase's rate;
--   solid, clear    the pairs that do not overlap and that Box2D finds apart too (its skin
--                   makes a few of the others touch): a manifold of no points each, no
--                   solver. Box2D's tests do less on a pair they find apart (the polygon
--                   test returns after its first or second search for a separating face,
--                   where a touching pair gets both and the clipping; the circle test
--                   returns at the first face the circle is beyond), so this is an upper
--                   bound on Box2D's rate over the workload (one of work done, pair for pair
--                   the searches' lengths vary);
--   solid, hits     the overlapping pairs, solver setup counted;
--   sensor, all     sensor fixtures: b2TestOverlap (GJK distance: a yes or no, no manifold,
--                   no solver) in place of the manifold.
-- Box2D computes in single precision and counts a polygon's skin (0.01 m, 0.3 px) as part of
-- it, so some pairs the oracle calls apart touch in Box2D (counted: wrong=).
local NARROW_GAP = 40 -- px kept between shapes that must not meet (Box2D's fat boxes add 3)
local NARROW_ROUNDS = 25
local NARROW_SAMPLE = 0.02 -- seconds per sample of steps
local NARROW_PER_BODY = 100 -- fixtures a body

-- Description d's shape centred at (x, y) of its body, turned by its angle.
local function narrowShape(d, x, y)
  if d.kind == 'rect' then return P.newRectangleShape(x, y, d.w, d.h, d.angle) end
  if d.kind == 'ngon' then
    return P.newPolygonShape(W.vertices({ kind = 'ngon', n = d.n, r = d.r, angle = d.angle, x = x, y = y }, true))
  end
  if d.kind == 'circle' then return P.newCircleShape(x, y, d.r) end
  error('no Box2D shape for ' .. tostring(d.kind))
end

-- A world of the pairs `sub`, laid out by W.layout: pairs 1-100 on the first two dynamic
-- bodies (at the origin, unturned), the first holding each pair's first shape and the second
-- each pair's second (a fixture each), pairs 101-200 on the next two, and so on. (Box2D looks
-- for an existing contact in a body's list of contacts before making one: a few bodies of
-- thousands of fixtures each would take seconds to build.) Density 0: a dynamic body then
-- keeps Box2D's mass of 1 and no rotational inertia, where the fixtures' own, summed over a
-- row of the grid, lose the inertia to rounding (single precision) and fail Box2D's check.
-- The bodies in a list.
local function narrowWorld(sub, apart, sensor)
  local ax, ay, bx, by = W.layout(sub, apart, NARROW_GAP)
  local world = P.newWorld(0, 0, false)
  local bodies, a, b = {}, nil, nil
  for i, p in ipairs(sub) do
    if (i - 1) % NARROW_PER_BODY == 0 then
      a, b = P.newBody(world, 0, 0, 'dynamic'), P.newBody(world, 0, 0, 'dynamic')
      bodies[#bodies + 1], bodies[#bodies + 2] = a, b
    end
    for _, f in ipairs({ P.newFixture(a, narrowShape(p[1], ax[i], ay[i]), 0),
      P.newFixture(b, narrowShape(p[2], bx[i], by[i]), 0) }) do
      f:setSensor(sensor)
      f:setUserData(i)
    end
  end
  return world, bodies
end

-- The pairs of list whose numbers idx holds, in that order.
local function subset(list, idx)
  local sub = {}
  for i, k in ipairs(idx) do sub[i] = list[k] end
  return sub
end

local function stepTime(world, n)
  local t0 = clock()
  for _ = 1, n do world:update(1 / 60, 0, 0) end
  return clock() - t0
end

local function positions(bodies)
  local p = {}
  for i, b in ipairs(bodies) do
    local x, y = b:getPosition()
    p[3 * i - 2], p[3 * i - 1], p[3 * i] = x, y, b:getAngle()
  end
  return p
end

local function narrowBox2D(name, list, set, idx, sensor)
  local sub = subset(list, idx)
  local wt, bt = narrowWorld(sub, false, sensor)
  local wa = narrowWorld(sub, true, sensor)
  for _ = 1, 3 do
    wt:update(1 / 60, 0, 0)
    wa:update(1 / 60, 0, 0)
  end
  local before = positions(bt)
  local per = math.min(stepTime(wt, 2), stepTime(wt, 2), stepTime(wt, 2)) / 2
  local n = math.max(2, math.floor(NARROW_SAMPLE / math.max(per, 1e-6) + 0.5))
  local bestT, bestA = math.huge, math.huge
  for _ = 1, NARROW_ROUNDS do
    bestT = math.min(bestT, stepTime(wt, n))
    bestA = math.min(bestA, stepTime(wa, n))
  end
  -- The contacts: one a pair, none apart; Box2D's verdicts against the oracle's; no body moved.
  local after, moved = positions(bt), 0
  for i = 1, #before, 3 do
    if after[i] ~= before[i] or after[i + 1] ~= before[i + 1] or after[i + 2] ~= before[i + 2] then
      moved = moved + 1
    end
  end
  local seen, touching, wrong, extra = {}, 0, 0, 0
  for _, c in ipairs(wt:getContacts()) do
    local fa, fb = c:getFixtures()
    local i = fa:getUserData()
    if i ~= fb:getUserData() or seen[i] then extra = extra + 1 else seen[i] = true end
    local t = c:isTouching()
    if t then touching = touching + 1 end
    if t ~= sub[i].hit then wrong = wrong + 1 end
  end
  local missing = 0
  for i = 1, #sub do if not seen[i] then missing = missing + 1 end end
  local perPair = (bestT - bestA) / n / #sub
  out(('box2d narrow lib=box2d workload=%s set=%s variant=%s pairs=%d steps=%d together=%.5f apart=%.5f rate=%.1f '
    .. 'contacts=%d missing=%d extra=%d apart_contacts=%d touching=%d wrong=%d moved=%d')
    :format(name, set, sensor and 'sensor' or 'solid', #sub, n, bestT / n * 1000, bestA / n * 1000, 1 / perPair,
      wt:getContactCount(), missing, extra, wa:getContactCount(), touching, wrong, moved))
  wt:destroy()
  wa:destroy()
  collectgarbage('collect')
end

local function narrowStrike(name, list, set, idx)
  local A = require('bench.adapters.strike')
  local sub = subset(list, idx)
  for _, method in ipairs(A.methods) do
    local As, Bs = {}, {}
    for i, p in ipairs(sub) do As[i], Bs[i] = method.build(p[1]), method.build(p[2]) end
    local wrongV, wrongD = H.verify(true, method, sub, As, Bs, 1, #sub)
    local rate, kb, timed = H.timeRow(method.test, As, Bs, #sub)
    out(('box2d narrow lib=strike workload=%s set=%s method=%s pairs=%d rate=%.1f kb=%.4f wrong=%d depths=%d timed=%d')
      :format(name, set, method.name, #sub, rate, kb, wrongV, wrongD, timed))
    collectgarbage('collect')
  end
end

-- The pairs of idx that Box2D finds apart (solid fixtures, after one step).
local function narrowClear(list, idx)
  local sub = subset(list, idx)
  local world = narrowWorld(sub, false, false)
  world:update(1 / 60, 0, 0)
  local touching = {}
  for _, c in ipairs(world:getContacts()) do
    if c:isTouching() then touching[c:getFixtures():getUserData()] = true end
  end
  world:destroy()
  local clear = {}
  for i, k in ipairs(idx) do
    if not touching[i] then clear[#clear + 1] = k end
  end
  return clear
end

local function narrow()
  for _, name in ipairs(opts.workloads) do
    local list = W.generate(name, opts.pairs, opts.seed)
    local all, hits, misses = {}, {}, {}
    for k, p in ipairs(list) do
      all[k] = k
      if p.hit then hits[#hits + 1] = k else misses[#misses + 1] = k end
    end
    local clear = narrowClear(list, misses)
    for _, s in ipairs({ { 'all', all }, { 'hits', hits }, { 'clear', clear } }) do
      narrowStrike(name, list, s[1], s[2])
    end
    narrowBox2D(name, list, 'all', all, false)
    narrowBox2D(name, list, 'clear', clear, false)
    narrowBox2D(name, list, 'hits', hits, false)
    narrowBox2D(name, list, 'all', all, true)
  end
end

function love.load(args)
  parse(args)
  out(('box2d version love=%s vm=%s'):format(table.concat({ love.getVersion() }, '.', 1, 3),
    jit and jit.version or _VERSION))
  local ok, err = pcall(function()
    if opts.section == 'narrow' then return narrow() end
    for _, n in ipairs(opts.n) do
      if opts.section == 'frame' then frames(n)
      elseif opts.section == 'rays' then rays(n)
      elseif opts.section == 'build' then buildTime(n)
      else error('unknown section ' .. tostring(opts.section)) end
    end
  end)
  if not ok then out('box2d error ' .. tostring(err)) end
  love.event.quit(ok and 0 or 1)
end
