--- Box2D, through LÖVE's love.physics, on bench/space.lua's workloads (the same seeded
--- worlds: bench/spaceworld.lua, loaded from the repository root, which must be the current
--- folder). bench/space.lua runs it when `love` is on the PATH:
---   love bench/lovephysics --section frame --n 1000,5000 --frames 60
---   love bench/lovephysics --section rays --rays 10000 --n 1000 --len 300
---   love bench/lovephysics --section build --n 20000
--- and reads the lines it prints, one result each, `box2d <section> key=value ...` (rays:
--- also one `box2d rayhit <ray> <body> <distance>` per ray that hits). No window.
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

local P = love.physics
local clock = os.clock
local jit = rawget(_G, 'jit')

local opts = { section = 'frame', n = { 1000 }, frames = 60, rays = 10000, len = 300 }

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

function love.load(args)
  parse(args)
  out(('box2d version love=%s vm=%s'):format(table.concat({ love.getVersion() }, '.', 1, 3),
    jit and jit.version or _VERSION))
  local ok, err = pcall(function()
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
