--- strike's S.pace beside the peers' worlds, on issue 11's "Speed" workloads. Not part of
--- make test. From the repository root, under any VM (`make bench-space` runs LuaJIT and
--- Lua 5.4):
---   luajit bench/space.lua [--n 1000,5000,20000,100000] [--frames 60] [--only strike,bump]
---                          [--sections frame,rays,build,churn,memory] [--hc-max 20000] [--save]
---                          [--jit love|stock]
--- Libraries (--only): strike (S.trikers colliders in S.pace), strike-shapes (bare S.hapes in
--- S.pace), and the peers found in $STRIKE_PEERS (HC, bump; checkouts named HC and bump.lua,
--- never part of this repository), through bench/adapters/space_*.lua; box2d (love.physics)
--- when `love` is on the PATH, through the LÖVE program bench/lovephysics/ run with io.popen
--- (it prints its results; this reads them). Missing ones are skipped with a note.
---
--- Sections (the worlds are bench/spaceworld.lua's, seeded, the same on every VM and in LÖVE):
---   frame   N bodies (a third boxes 8-24 px, a third 4-8-gons of circumradius 5-14, a third
---           circles of radius 4-12) in a square of side 40 sqrt(N), each moving 0.5-2 px a
---           frame and bouncing off the border. A frame = move every body + every colliding
---           pair (strike: space:collisions(out)). ms per frame (median and min over the timed
---           frames, os.clock, the GC running as usual, after warm-up frames; --frames F times
---           F frames up to N = 5,000 and F * 5000 / N (at least 5) above), KB allocated per
---           frame (two frames with the GC stopped, after one; on LuaJIT with the count of
---           traces compiled in them, since a trace is a GC object), the pairs found in the
---           last timed frame, LuaJIT trace flushes and aborts during the timed frames
---           (jit.attach; the trace cache is flushed after each library's world is built,
---           before its frames), and the time to build and add the world.
---           HC is run up to --hc-max bodies (default 20,000: it takes seconds a frame above).
---           strike's pairs are checked once against a brute force (S.triking on every pair of
---           bodies, in add order) on the 1,000-body world, before any frame and after 30.
---   rays    10,000 closest-hit rays 300 px long from uniform points in uniform directions,
---           against the 1,000-body world (not moving): rays per second (best of 3 passes after
---           one), each answer checked against a brute force over every body's rayCast (with
---           a bounding-box test first): same distance within 1e-9 relative (absolute below
---           1 px) and the same body, or another at that same distance. Peers are checked the
---           same way with their own tolerance (HC 1e-7 relative; Box2D 0.01 px, single
---           precision); bump's boxes are not shapes, so its answers are not checked. On
---           LuaJIT, the trace flushes and aborts during the 3 timed passes (Box2D's: '—').
---   build   constructing the 20,000 bodies of the mix, adding them to a world, and the first
---           query after (one closest-hit ray: strike and Box2D's trees take the bodies in at
---           their first query or step, not at the add), best of 3.
---   churn   a 1,000-body world (not moving) and 100 bullets (circles of radius 2): each frame
---           removes the 100 bullets, builds 100 new ones at new places and adds them, then
---           finds every colliding pair; ms per frame for each of the four steps, medians over
---           60 frames after 10.
---   memory  bytes per body (collectgarbage('count') before and after, after full
---           collections): 20,000 S.trikers.Rectangle colliders, 20,000 bare Rectangles, the
---           mix as colliders and as shapes, what a first getBounds adds (strike fills its
---           caches on the first query, and adding a body to a space reads its bounds), and
---           what adding them to a space adds; the peers' bodies and worlds beside them.
--- --save writes every number to bench/results/space-<vm>.csv (space-luajit-stock.csv with
--- --jit stock). The run fails (exit status 1,
--- after the tables) when strike's pairs or rays disagree with the brute force.
package.path = './?.lua;./?/init.lua;' .. package.path

local SW = require('bench.spaceworld')
local H = require('bench.harness')
local fmt, tableOut, fullGC = H.fmt, H.tableOut, H.fullGC

local clock = os.clock
local jit = rawget(_G, 'jit')
local abs, max, min, huge = math.abs, math.max, math.min, math.huge

local opts = { n = { 1000, 5000, 20000, 100000 }, frames = 60, only = nil, save = false, hcMax = 20000,
  sections = { frame = true, rays = true, build = true, churn = true, memory = true } }
do
  local list = H.list
  local i = 1
  while arg[i] do
    local a, v = arg[i], arg[i + 1]
    if a == '--n' then opts.n = list(v); i = i + 1
    elseif a == '--frames' then opts.frames = tonumber(v); i = i + 1
    elseif a == '--hc-max' then opts.hcMax = tonumber(v); i = i + 1
    elseif a == '--only' then
      opts.only = {}
      for _, name in ipairs(list(v)) do opts.only[name] = true end
      i = i + 1
    elseif a == '--sections' then
      opts.sections = {}
      for _, name in ipairs(list(v)) do opts.sections[name] = true end
      i = i + 1
    elseif a == '--save' then opts.save = true
    elseif a == '--jit' then opts.jit = v; i = i + 1
    else error('unknown option ' .. a) end
    i = i + 1
  end
end

-- LuaJIT's limits: LÖVE's by default, as a game runs (LÖVE 11.4's boot.lua raises them:
-- maxtrace 2000, maxrecord 8000, maxmcode 16384 KB; the issue's flush target is under these),
-- or the standalone interpreter's own with --jit stock.
local JIT_LIMITS = H.jitLimits(opts.jit)

local RAYS, RAY_N, RAY_LEN = 10000, 1000, 300
local BUILD_N, MEMORY_N = 20000, 20000
local CHURN_N, CHURN_BULLETS, CHURN_FRAMES, CHURN_WARM = 1000, 100, 60, 10
local CHECK_N, CHECK_FRAMES = 1000, 30

local vmName = jit and jit.version or _VERSION
local vmFile = jit and ('luajit' .. (JIT_LIMITS == 'stock' and '-stock' or '')) or _VERSION:gsub('Lua ', 'lua')

local function wanted(name) return not opts.only or opts.only[name] end

local function note(s) io.stderr:write(s, '\n') io.stderr:flush() end

-- Libraries: strike's two variants, then the peers found.
local libs, skipped = {}, {}
do
  local ok, S = pcall(require, 'strike')
  if not ok then
    skipped[#skipped + 1] = 'strike (' .. tostring(S) .. ')'
  elseif type(S.pace) ~= 'function' then
    skipped[#skipped + 1] = 'strike (no S.pace in this checkout)'
  else
    local A = require('bench.adapters.space_strike')
    if wanted('strike') then libs[#libs + 1] = A.colliders end
    if wanted('strike-shapes') then libs[#libs + 1] = A.shapes end
  end
end
H.peers({ { 'bump.lua', 'bump', 'bench.adapters.space_bump' },
  { 'HC', 'HC', 'bench.adapters.space_hc' } }, wanted, libs, skipped,
  'HC, bump (set STRIKE_PEERS to a folder with HC and bump.lua checkouts)')
local function findLib(name)
  for _, l in ipairs(libs) do if l.name == name then return l end end
end

-- Box2D through LÖVE: `love` on the PATH (run without a display first, then under xvfb-run).
local love
if wanted('box2d') then
  if H.loveOnPath() then love = true else skipped[#skipped + 1] = 'box2d (no love on the PATH)' end
end
local runLove = H.runLove

-- LuaJIT trace events during timed frames.
local flushes, aborts, traces, counting = 0, 0, 0, false
if jit and jit.attach then
  jit.attach(function(what)
    if counting then
      if what == 'flush' then flushes = flushes + 1
      elseif what == 'abort' then aborts = aborts + 1
      elseif what == 'stop' then traces = traces + 1 end
    end
  end, 'trace')
end

-- Every number, for the CSV: section, library, n, metric, value.
local csv = {}
local function put(section, lib, n, metric, value)
  csv[#csv + 1] = { section, lib, n, metric, value }
end


-- Before each library's run of a section: no garbage and, on LuaJIT, no traces left from
-- the one before.
local function fresh()
  fullGC()
  if jit then jit.flush() end
end

local step = SW.step
local function frame(lib, st, w)
  step(w)
  lib.move(st, w)
  return lib.collide(st)
end

local t00 = os.time()
note(('strike space bench on %s%s'):format(vmName, jit and (' (JIT limits: ' .. JIT_LIMITS .. ')') or ''))

---------------------------------------------------------------------------------------------
-- Frame workload.
local frameRows = {} -- { n =, lib =, frames =, median =, min =, kb =, pairs =, flushes =, aborts =, build = }
local checks = {} -- strike's brute-force checks: { lib =, at =, pairs =, ok =, why = }

-- strike's pairs against S.triking on every pair of bodies, in add order.
local function bruteCheck(lib)
  local S = require('strike')
  local w = SW.world(CHECK_N, SW.seed(CHECK_N))
  local st = lib.build(w)
  local mtv = S.MTV()
  local done = 0
  for _, at in ipairs({ 0, CHECK_FRAMES }) do
    while done < at do frame(lib, st, w); done = done + 1 end
    local out, n = st.space:collisions(st.out)
    local bodies, k, why = st.bodies, 0, nil
    for i = 1, w.n - 1 do
      local a = bodies[i]
      for j = i + 1, w.n do
        local m = S.triking(a, bodies[j], mtv)
        if m then
          k = k + 1
          local r = out[k]
          if not why then
            if k > n then why = ('pair %d (%d, %d) missing'):format(k, i, j)
            elseif r.a ~= a or r.b ~= bodies[j] then
              why = ('pair %d is (%s, %s), expected (%d, %d)'):format(k, tostring(st.index[r.a]),
                tostring(st.index[r.b]), i, j)
            elseif abs(r.mtv.x - m.x) > 1e-9 * max(1, abs(m.x)) or abs(r.mtv.y - m.y) > 1e-9 * max(1, abs(m.y)) then
              why = ('pair %d (%d, %d): MTV %.17g, %.17g, expected %.17g, %.17g'):format(k, i, j, r.mtv.x, r.mtv.y,
                m.x, m.y)
            end
          end
        end
      end
    end
    if not why and k ~= n then why = ('%d pairs, brute force %d'):format(n, k) end
    checks[#checks + 1] = { lib = lib.name, at = at, pairs = k, ok = not why, why = why }
    put('check', lib.name, CHECK_N, 'frame' .. at .. '_ok', why and 0 or 1)
    note(('  check %-13s N=%d frame %2d: %d pairs, %s'):format(lib.name, CHECK_N, at, k, why or 'equal'))
  end
end

local function runFrames(lib, n)
  local w = SW.world(n, SW.seed(n))
  fullGC()
  local t0 = clock()
  local st = lib.build(w)
  local buildMs = (clock() - t0) * 1000
  if jit then jit.flush() end
  local timed, warm = SW.frames(opts.frames, n)
  for _ = 1, warm do frame(lib, st, w) end
  fullGC()
  local times, count = {}, 0
  flushes, aborts, counting = 0, 0, true
  for f = 1, timed do
    local f0 = clock()
    count = frame(lib, st, w)
    times[f] = (clock() - f0) * 1000
  end
  counting = false
  local fl, ab = flushes, aborts
  -- allocation: the second and third of three frames with the GC stopped (LuaJIT: a trace
  -- is a GC object, so traces compiled in those frames count too; they are counted)
  fullGC()
  collectgarbage('stop')
  frame(lib, st, w)
  local kb0 = collectgarbage('count')
  traces, counting = 0, true
  frame(lib, st, w)
  frame(lib, st, w)
  counting = false
  local kb = (collectgarbage('count') - kb0) / 2
  collectgarbage('restart')
  local med, mn = SW.medianMin(times)
  return { n = n, lib = lib.name, frames = timed, warm = warm, median = med, min = mn, kb = kb, pairs = count,
    flushes = jit and fl, aborts = jit and ab, kbTraces = jit and traces, build = buildMs }
end

if opts.sections.frame then
  for _, lib in ipairs(libs) do
    if lib.name:match('^strike') then
      local ok, err = pcall(bruteCheck, lib)
      if not ok then
        checks[#checks + 1] = { lib = lib.name, at = -1, pairs = 0, ok = false, why = tostring(err) }
        note('  check ' .. lib.name .. ' FAILED: ' .. tostring(err))
      end
      fullGC()
    end
  end
  for _, n in ipairs(opts.n) do
    for _, lib in ipairs(libs) do
      if lib.name == 'HC' and n > opts.hcMax then
        frameRows[#frameRows + 1] = { n = n, lib = lib.name, skip = ('not run above --hc-max %d'):format(opts.hcMax) }
      else
        local c0 = clock()
        local ok, r = pcall(runFrames, lib, n)
        if not ok then r = { n = n, lib = lib.name, skip = 'ERROR: ' .. tostring(r) } end
        frameRows[#frameRows + 1] = r
        if r.skip then note(('  frame %-13s N=%-6d %s'):format(lib.name, n, r.skip))
        else
          note(('  frame %-13s N=%-6d %8.2f ms (min %.2f) %8.2f KB/frame %6d pairs %s %.1f s'):format(lib.name, n,
            r.median, r.min, r.kb, r.pairs, jit and ('flushes ' .. r.flushes) or '', clock() - c0))
        end
        fullGC()
      end
    end
  end
  if love then
    local ns = {}
    for _, n in ipairs(opts.n) do ns[#ns + 1] = tostring(n) end
    local recs, err = runLove(('--section frame --n %s --frames %d'):format(table.concat(ns, ','), opts.frames))
    if recs then
      for _, r in ipairs(recs) do
        if r.kind == 'frame' then
          frameRows[#frameRows + 1] = { n = r.n, lib = 'box2d', frames = r.frames, warm = r.warm, median = r.median,
            min = r.min, kb = r.kb, pairs = r.pairs, flushes = jit and r.flushes, aborts = jit and r.aborts,
            build = r.build, loveFlushes = r.flushes, loveAborts = r.aborts }
          note(('  frame %-13s N=%-6d %8.2f ms (min %.2f) %6d pairs, LÖVE'):format('box2d', r.n, r.median, r.min,
            r.pairs))
        end
      end
    else
      skipped[#skipped + 1] = 'box2d frame (' .. tostring(err) .. ')'
    end
  end
end

---------------------------------------------------------------------------------------------
-- Rays.
local rayRows = {} -- { lib =, rate =, correct =, total =, correctOut =, totalOut =, checked = bool, note = }
local bruteRate
if opts.sections.rays then
  local S = findLib('strike') or findLib('strike-shapes')
  local w = SW.world(RAY_N, SW.seed(RAY_N))
  local R = SW.rays(RAYS, w.side, SW.seed(RAY_N) + 1)
  local ox, oy, rdx, rdy = R.ox, R.oy, R.dx, R.dy
  -- The brute force: strike colliders (or shapes) for every body, every one tried.
  local Sl = S or require('bench.adapters.space_strike').colliders
  local okS = pcall(require, 'strike')
  local bI, bD, inside = {}, {}, {}
  local bodies = {}
  if okS then
    for i = 1, w.n do bodies[i] = Sl.make(w, i) end
    local x0, y0, x1, y1 = {}, {}, {}, {}
    for i = 1, w.n do x0[i], y0[i], x1[i], y1[i] = bodies[i]:getBounds() end
    local function brute(record)
      for k = 1, R.count do
        local x, y, dx, dy = ox[k], oy[k], rdx[k], rdy[k]
        local ex, ey = x + dx * RAY_LEN, y + dy * RAY_LEN
        local sx0, sx1 = min(x, ex), max(x, ex)
        local sy0, sy1 = min(y, ey), max(y, ey)
        local best, bestD, ins = nil, huge, false
        for i = 1, w.n do
          if x0[i] <= sx1 and x1[i] >= sx0 and y0[i] <= sy1 and y1[i] >= sy0 then
            local d = bodies[i]:rayCast(x, y, dx, dy, RAY_LEN)
            if d and d < bestD then best, bestD = i, d end
            if record and not ins and bodies[i]:containsPoint(x, y) then ins = true end
          end
        end
        if record then bI[k], bD[k], inside[k] = best, best and bestD, ins end
      end
    end
    fresh()
    brute(true)
    local t0 = clock()
    brute(false)
    bruteRate = R.count / (clock() - t0)
    put('rays', Sl.name .. '-brute', RAY_N, 'rays_per_s', bruteRate)
  end
  -- Is answer (i, d) to ray k right? Within tol(d): the same distance, and the same body or
  -- one that strike's rayCast puts at that distance too.
  local function right(k, i, d, tol)
    if bI[k] == nil then return i == nil end
    if i == nil then return false end
    if abs(d - bD[k]) > tol(bD[k]) then return false end
    if i == bI[k] then return true end
    local di = bodies[i]:rayCast(ox[k], oy[k], rdx[k], rdy[k], RAY_LEN)
    return di ~= nil and abs(di - bD[k]) <= tol(bD[k])
  end
  local notes = {
    bump = 'bounding boxes only: not checked',
    HC = 'HC:raycast looks in the cells from (x + dx range, y + dy range) to (x, y), none when dx > 0 or dy > 0',
    box2d = 'Box2D reports no hit for a ray that starts inside a shape',
  }
  local tols = {
    strike = function(d) return 1e-9 * max(1, d) end,
    HC = function(d) return 1e-7 * max(1, d) end,
    box2d = function() return 0.01 end,
  }
  tols['strike-shapes'] = tols.strike
  local function score(name, gotI, gotD, rate, extra)
    local row = { lib = name, rate = rate, checked = okS and tols[name] ~= nil, note = extra }
    if row.checked then
      local c, t, cOut, tOut = 0, 0, 0, 0
      for k = 1, R.count do
        local good = right(k, gotI[k], gotD[k], tols[name])
        t = t + 1
        if good then c = c + 1 end
        if not inside[k] then
          tOut = tOut + 1
          if good then cOut = cOut + 1 end
        end
      end
      row.correct, row.total, row.correctOut, row.totalOut = c, t, cOut, tOut
      if c < t then -- where the wrong answers are: by the direction's quadrant
        local q = {}
        for k = 1, R.count do
          local key = (rdx[k] < 0 and '-x' or '+x') .. (rdy[k] < 0 and '-y' or '+y')
          q[key] = q[key] or { 0, 0 }
          q[key][2] = q[key][2] + 1
          if right(k, gotI[k], gotD[k], tols[name]) then q[key][1] = q[key][1] + 1 end
        end
        local parts = {}
        for _, key in ipairs({ '+x+y', '-x+y', '+x-y', '-x-y' }) do
          if q[key] then parts[#parts + 1] = ('%s %.1f %%'):format(key, 100 * q[key][1] / q[key][2]) end
        end
        row.quadrants = table.concat(parts, ', ')
      end
      put('rays', name, RAY_N, 'correct_pct', 100 * c / t)
      put('rays', name, RAY_N, 'correct_pct_origin_outside', 100 * cOut / tOut)
    end
    put('rays', name, RAY_N, 'rays_per_s', rate)
    rayRows[#rayRows + 1] = row
    note(('  rays  %-13s %10.0f rays/s%s'):format(name, rate,
      row.checked and ('  %.2f %% correct'):format(100 * row.correct / row.total) or ''))
  end
  for _, lib in ipairs(libs) do
    fresh()
    local ok, err = pcall(function()
      local st = lib.build(w)
      local ray = lib.ray
      local gotI, gotD = {}, {}
      local function pass(record)
        for k = 1, R.count do
          local i, d = ray(st, ox[k], oy[k], rdx[k], rdy[k], RAY_LEN)
          if record then gotI[k], gotD[k] = i, d end
        end
      end
      pass(true)
      local best = huge
      flushes, aborts, counting = 0, 0, true
      for _ = 1, 3 do
        local t0 = clock()
        pass(false)
        best = min(best, clock() - t0)
      end
      counting = false
      score(lib.name, gotI, gotD, R.count / best, notes[lib.name])
      if jit then
        local row = rayRows[#rayRows]
        row.flushes, row.aborts = flushes, aborts
        put('rays', lib.name, RAY_N, 'trace_flushes', flushes)
        put('rays', lib.name, RAY_N, 'trace_aborts', aborts)
      end
    end)
    if not ok then rayRows[#rayRows + 1] = { lib = lib.name, err = tostring(err) } end
    fullGC()
  end
  if love then
    local recs, err = runLove(('--section rays --n %d --rays %d --len %d'):format(RAY_N, RAYS, RAY_LEN))
    if recs then
      local gotI, gotD, rate = {}, {}, nil
      for _, r in ipairs(recs) do
        if r.kind == 'rayhit' then gotI[r.ray], gotD[r.ray] = r.body, r.d
        elseif r.kind == 'rays' then rate = r.rate end
      end
      score('box2d', gotI, gotD, rate, notes.box2d)
    else
      skipped[#skipped + 1] = 'box2d rays (' .. tostring(err) .. ')'
    end
  end
end

---------------------------------------------------------------------------------------------
-- Build + add.
local buildRows = {} -- { lib =, make =, add =, first =, total = } (ms)
if opts.sections.build then
  local w = SW.world(BUILD_N, SW.seed(BUILD_N))
  for _, lib in ipairs(libs) do
    fresh()
    local ok, err = pcall(function()
      local bm, ba, bq, bt = huge, huge, huge, huge
      for _ = 1, 3 do
        fullGC()
        local made = {}
        local t0 = clock()
        for i = 1, w.n do made[i] = lib.make(w, i) end
        local t1 = clock()
        local st = lib.new()
        for i = 1, w.n do lib.add(st, made[i], i) end
        local t2 = clock()
        lib.ray(st, 0, 0, 1, 0, 1)
        local t3 = clock()
        bm, ba, bq, bt = min(bm, t1 - t0), min(ba, t2 - t1), min(bq, t3 - t2), min(bt, t3 - t0)
      end
      buildRows[#buildRows + 1] = { lib = lib.name, make = bm * 1000, add = ba * 1000, first = bq * 1000,
        total = bt * 1000 }
      put('build', lib.name, BUILD_N, 'make_ms', bm * 1000)
      put('build', lib.name, BUILD_N, 'add_ms', ba * 1000)
      put('build', lib.name, BUILD_N, 'first_query_ms', bq * 1000)
      put('build', lib.name, BUILD_N, 'total_ms', bt * 1000)
      note(('  build %-13s N=%d make %.1f ms + add %.1f ms + first query %.1f ms'):format(lib.name, BUILD_N,
        bm * 1000, ba * 1000, bq * 1000))
    end)
    if not ok then buildRows[#buildRows + 1] = { lib = lib.name, err = tostring(err) } end
    fullGC()
  end
  if love then
    local recs, err = runLove(('--section build --n %d'):format(BUILD_N))
    local r = recs and recs[#recs]
    if r and r.kind == 'build' then
      buildRows[#buildRows + 1] = { lib = 'box2d', total = r.ms }
      put('build', 'box2d', BUILD_N, 'total_ms', r.ms)
    else
      skipped[#skipped + 1] = 'box2d build (' .. tostring(err) .. ')'
    end
  end
end

---------------------------------------------------------------------------------------------
-- Churn.
local churnRows = {} -- { lib =, remove =, build =, add =, pairs =, frame =, kb =, count = } (ms, medians)
if opts.sections.churn then
  local w = SW.world(CHURN_N, SW.seed(CHURN_N))
  local total = CHURN_WARM + CHURN_FRAMES + 4
  local B = SW.bullets(CHURN_BULLETS * total, w.side, SW.seed(CHURN_N) + 2)
  for _, lib in ipairs(libs) do
    fresh()
    local ok, err = pcall(function()
      local st = lib.build(w)
      local live, made, next = {}, {}, 1
      local bullet, add, remove, collide = lib.bullet, lib.add, lib.remove, lib.collide
      local n0 = w.n
      -- One frame: remove the live bullets, build new ones, add them, find the pairs; the
      -- four times (s) and the pair count.
      local function churnFrame()
        local t0 = clock()
        for k = 1, CHURN_BULLETS do remove(st, live[k]) end
        local t1 = clock()
        for k = 1, CHURN_BULLETS do
          made[k] = bullet(B.x[next], B.y[next])
          next = next + 1
        end
        local t2 = clock()
        for k = 1, CHURN_BULLETS do
          add(st, made[k], n0 + k)
          live[k] = made[k]
        end
        local t3 = clock()
        local count = collide(st)
        return t1 - t0, t2 - t1, t3 - t2, clock() - t3, count
      end
      for k = 1, CHURN_BULLETS do
        live[k] = bullet(B.x[next], B.y[next])
        next = next + 1
        add(st, live[k], n0 + k)
      end
      collide(st)
      for _ = 1, CHURN_WARM do churnFrame() end
      fullGC()
      local tr, tb, ta, tra, tp, tf, count = {}, {}, {}, {}, {}, {}, 0
      for f = 1, CHURN_FRAMES do
        local r1, b1, a1, p1
        r1, b1, a1, p1, count = churnFrame()
        tr[f], tb[f], ta[f], tra[f] = r1 * 1000, b1 * 1000, a1 * 1000, (r1 + a1) * 1000
        tp[f], tf[f] = p1 * 1000, (r1 + b1 + a1 + p1) * 1000
      end
      fullGC()
      collectgarbage('stop')
      churnFrame()
      local kb0 = collectgarbage('count')
      churnFrame()
      churnFrame()
      local kb = (collectgarbage('count') - kb0) / 2
      collectgarbage('restart')
      local r = { lib = lib.name, remove = (SW.medianMin(tr)), build = (SW.medianMin(tb)), add = (SW.medianMin(ta)),
        removeAdd = (SW.medianMin(tra)), pairs = (SW.medianMin(tp)), frame = (SW.medianMin(tf)), kb = kb,
        count = count }
      churnRows[#churnRows + 1] = r
      for _, m in ipairs({ 'remove', 'build', 'add', 'removeAdd', 'pairs', 'frame' }) do
        put('churn', lib.name, CHURN_N, m .. '_ms', r[m])
      end
      put('churn', lib.name, CHURN_N, 'kb_per_frame', kb)
      note(('  churn %-13s remove %.3f + build %.3f + add %.3f + pairs %.3f ms, %.1f KB/frame'):format(lib.name,
        r.remove, r.build, r.add, r.pairs, kb))
    end)
    if not ok then churnRows[#churnRows + 1] = { lib = lib.name, err = tostring(err) } end
    fullGC()
  end
end

---------------------------------------------------------------------------------------------
-- Memory: bytes per body.
local memRows = {} -- { what =, bytes = }
if opts.sections.memory then
  local w = SW.world(MEMORY_N, SW.seed(MEMORY_N))
  local n = w.n
  -- Bytes per body that `fn(keep)` leaves reachable from keep (pre-sized, so that the list
  -- itself does not count).
  local function bytes(fn, keep)
    keep = keep or {}
    for i = 1, n do keep[i] = keep[i] or false end
    fullGC()
    local before = collectgarbage('count')
    local extra = fn(keep)
    fullGC()
    local b = (collectgarbage('count') - before) * 1024 / n
    return b, extra
  end
  local function row(what, b)
    memRows[#memRows + 1] = { what = what, bytes = b }
    put('memory', what, n, 'bytes_per_body', b)
    note(('  memory %-60s %7.0f bytes/body'):format(what, b))
  end
  local okS, S = pcall(require, 'strike')
  local function bounds(keep)
    for i = 1, n do keep[i]:getBounds() end
  end
  if okS and (wanted('strike') or wanted('strike-shapes')) then
    local kinds = { { 'S.trikers.Rectangle', S.trikers.Rectangle }, { 'S.hapes.Rectangle', S.hapes.Rectangle } }
    for _, c in ipairs(kinds) do
      local keep = {}
      row(c[1] .. '(x, y, 16, 12), built', bytes(function(k)
        for i = 1, n do k[i] = c[2](w.x[i], w.y[i], 16, 12) end
      end, keep))
      row(c[1] .. ': more after a first getBounds', bytes(bounds, keep))
    end
  end
  for _, lib in ipairs(libs) do
    local keep = {}
    row(lib.name .. ': the mix, built', bytes(function(k)
      for i = 1, n do k[i] = lib.make(w, i) end
    end, keep))
    if lib.name:match('^strike') then row(lib.name .. ': more after a first getBounds', bytes(bounds, keep)) end
    local st
    row(lib.name .. ': added to a world (world + per-body cost)', bytes(function()
      st = lib.new()
      for i = 1, n do lib.add(st, keep[i], i) end
    end, keep))
    st = nil -- luacheck: ignore 311
    fullGC()
  end
end

---------------------------------------------------------------------------------------------
-- Tables.

print(('strike space bench — %s%s'):format(vmName, jit and (' (JIT limits: ' .. JIT_LIMITS .. ')') or ''))
for _, l in ipairs(libs) do print(('  %-13s %s'):format(l.name, l.note)) end
if love then print(('  %-13s %s'):format('box2d', 'love.physics: dynamic bodies, sensor fixtures, setPosition, '
  .. 'world:update(1/60) + getContacts (isTouching counted); LÖVE\'s LuaJIT')) end
print()

if opts.sections.frame then
  print('Frame: move every body + find every colliding pair (ms per frame, os.clock)')
  local rows = {}
  for _, r in ipairs(frameRows) do
    if r.skip then
      rows[#rows + 1] = { tostring(r.n), r.lib, '—', '—', '—', '—', '—', '—', '—', r.skip }
    else
      put('frame', r.lib, r.n, 'ms_median', r.median)
      put('frame', r.lib, r.n, 'ms_min', r.min)
      put('frame', r.lib, r.n, 'kb_per_frame', r.kb)
      put('frame', r.lib, r.n, 'pairs', r.pairs)
      put('frame', r.lib, r.n, 'frames', r.frames)
      put('frame', r.lib, r.n, 'build_ms', r.build)
      local fl = r.loveFlushes or r.flushes
      if fl then
        put('frame', r.lib, r.n, 'trace_flushes', fl)
        put('frame', r.lib, r.n, 'trace_aborts', r.loveAborts or r.aborts)
      end
      if r.kbTraces then put('frame', r.lib, r.n, 'traces_in_kb_frames', r.kbTraces) end
      rows[#rows + 1] = { tostring(r.n), r.lib, ('%d (+%d)'):format(r.frames, r.warm), fmt(r.median), fmt(r.min),
        fmt(r.kb, 1) .. ((r.kbTraces and r.kbTraces > 0) and (' (%d traces)'):format(r.kbTraces) or ''),
        (fmt(r.pairs, 1):gsub('%.0$', '')), fl and tostring(fl) or '—',
        fl and tostring(r.loveAborts or r.aborts) or '—', fmt(r.build, 1) }
    end
  end
  tableOut({ 'N', 'library', 'frames (+warm-up)', 'ms/frame median', 'min', 'KB/frame', 'pairs (last frame)',
    'trace flushes', 'trace aborts', 'build+add ms' }, rows)

  -- Side by side: medians, and strike's time as a fraction of each peer's.
  local names = {}
  for _, r in ipairs(frameRows) do
    local seen = false
    for _, nm in ipairs(names) do seen = seen or nm == r.lib end
    if not seen then names[#names + 1] = r.lib end
  end
  local function get(lib, n)
    for _, r in ipairs(frameRows) do if r.lib == lib and r.n == n and not r.skip then return r end end
  end
  local head = { 'N' }
  for _, nm in ipairs(names) do head[#head + 1] = nm .. ' ms' end
  local peers = {}
  for _, nm in ipairs(names) do if not nm:match('^strike') then peers[#peers + 1] = nm end end
  for _, p in ipairs(peers) do head[#head + 1] = 'strike ÷ ' .. p end
  local rows2 = {}
  for _, n in ipairs(opts.n) do
    local cells = { tostring(n) }
    for _, nm in ipairs(names) do
      local r = get(nm, n)
      cells[#cells + 1] = r and fmt(r.median) or '—'
    end
    local s = get('strike', n)
    for _, p in ipairs(peers) do
      local r = get(p, n)
      cells[#cells + 1] = (s and r) and ('%.2f×'):format(s.median / r.median) or '—'
    end
    rows2[#rows2 + 1] = cells
  end
  print('Side by side (median ms per frame; strike ÷ peer = strike\'s time over the peer\'s, below 1 = strike faster)')
  tableOut(head, rows2)
  -- Growth from the smallest N to the largest, against linear.
  local lo, hi = opts.n[1], opts.n[#opts.n]
  if hi ~= lo then
    local g = {}
    for _, nm in ipairs(names) do
      local a, b = get(nm, lo), get(nm, hi)
      if a and b then
        local ratio = (b.median / a.median) / (hi / lo)
        g[#g + 1] = ('%s %.2f'):format(nm, ratio)
        put('frame', nm, hi, 'growth_vs_linear_from_' .. lo, ratio)
      end
    end
    print(('Growth from N = %d to %d, as a multiple of linear (1 = linear): %s'):format(lo, hi, table.concat(g, ', ')))
  end
  for _, c in ipairs(checks) do
    print(('Brute-force check (%s, N = %d, after %d frames): %s'):format(c.lib, CHECK_N, c.at,
      c.ok and ('%d pairs, the same pairs in the same order with the same MTVs'):format(c.pairs)
      or ('MISMATCH: ' .. tostring(c.why))))
  end
  if jit then
    print('Trace flushes/aborts: LuaJIT events during the timed frames (box2d: inside LÖVE). KB/frame: '
      .. '(n traces) = n traces were compiled during the two measured frames, and a trace is a GC object.')
  end
  if not jit and love then print('box2d runs in LÖVE, under its LuaJIT, whatever the VM here.') end
  print()
end

if opts.sections.rays then
  print(('Rays: %d closest-hit casts, %d px, against the %d-body world (rays/s, best of 3)'):format(RAYS, RAY_LEN,
    RAY_N))
  local rows = {}
  if bruteRate then
    rows[#rows + 1] = { 'strike brute force (bounds test + rayCast per body)', fmt(bruteRate, 0), '(reference)', '',
      '' }
  end
  for _, r in ipairs(rayRows) do
    if r.err then rows[#rows + 1] = { r.lib, 'ERROR', r.err, '', '' }
    else
      rows[#rows + 1] = { r.lib, fmt(r.rate, 0),
        r.checked and ('%.2f %% (%d / %d)'):format(100 * r.correct / r.total, r.correct, r.total) or (r.note or '—'),
        r.checked and ('%.2f %%'):format(100 * r.correctOut / r.totalOut) or '—',
        r.flushes and ('%d / %d'):format(r.flushes, r.aborts) or '—' }
    end
  end
  tableOut({ 'library', 'rays/s', 'correct', 'correct, origin outside every body',
    'trace flushes / aborts (timed passes)' }, rows)
  for _, r in ipairs(rayRows) do
    if r.checked and r.note then print(('%s: %s'):format(r.lib, r.note)) end
    if r.quadrants then print(('%s, correct by direction: %s'):format(r.lib, r.quadrants)) end
  end
  print()
end

if opts.sections.build then
  print(('Build + add + first query: %d bodies of the mix (ms, best of 3; box2d: build and add)'):format(BUILD_N))
  local rows = {}
  for _, r in ipairs(buildRows) do
    if r.err then rows[#rows + 1] = { r.lib, 'ERROR', r.err, '', '', '' }
    else
      rows[#rows + 1] = { r.lib, fmt(r.make, 1), fmt(r.add, 1), fmt(r.first, 1), fmt(r.total, 1),
        ('%.2f'):format(r.total * 1000 / BUILD_N) }
    end
  end
  tableOut({ 'library', 'construct ms', 'add ms', 'first query ms', 'total ms', 'µs/body' }, rows)
end

if opts.sections.churn then
  print(('Churn: %d static bodies; each frame the %d bullets (circles of radius 2) removed, %d new ones built '
    .. 'and added, then every pair (ms, medians of %d frames; KB/frame includes building the bullets)')
    :format(CHURN_N, CHURN_BULLETS, CHURN_BULLETS, CHURN_FRAMES))
  local rows = {}
  for _, r in ipairs(churnRows) do
    if r.err then rows[#rows + 1] = { r.lib, 'ERROR', r.err, '', '', '', '', '', '' }
    else
      rows[#rows + 1] = { r.lib, fmt(r.remove, 3), fmt(r.build, 3), fmt(r.add, 3),
        fmt(r.removeAdd, 3), fmt(r.pairs, 3), fmt(r.frame, 3), fmt(r.kb, 1),
        (fmt(r.count, 1):gsub('%.0$', '')) }
    end
  end
  tableOut({ 'library', 'remove 100 ms', 'build 100 ms', 'add 100 ms', 'remove + add ms', 'pairs ms', 'frame ms',
    'KB/frame', 'pairs' }, rows)
end

if opts.sections.memory then
  print(('Memory: bytes per body, %d bodies, %s'):format(MEMORY_N, vmName))
  local rows = {}
  for _, r in ipairs(memRows) do rows[#rows + 1] = { r.what, fmt(r.bytes, 0) } end
  tableOut({ 'what', 'bytes/body' }, rows)
end

-- strike's answers that disagree with the brute force fail the run (after the tables).
local failed = {}
for _, c in ipairs(checks) do
  if not c.ok then failed[#failed + 1] = ('%s pairs after %d frames'):format(c.lib, c.at) end
end
for _, r in ipairs(rayRows) do
  if r.lib:match('^strike') and (r.err or (r.checked and r.correct < r.total)) then
    failed[#failed + 1] = r.lib .. ' rays'
  end
end
if #skipped > 0 then print('skipped: ' .. table.concat(skipped, '; ')) end
print(('(%d s in all)'):format(os.time() - t00))

if opts.save then
  local path = 'bench/results/space-' .. vmFile .. '.csv'
  local f = assert(io.open(path, 'w'))
  f:write('vm,section,library,n,metric,value\n')
  for _, r in ipairs(csv) do
    f:write(('%s,%s,%s,%d,%s,%.6g\n'):format(vmName .. (jit and (' ' .. JIT_LIMITS) or ''), r[1], r[2], r[3], r[4],
      r[5]))
  end
  f:close()
  print('saved ' .. path)
end
if #failed > 0 then
  print('FAILED (strike disagrees with the brute force): ' .. table.concat(failed, ', '))
  os.exit(1)
end
