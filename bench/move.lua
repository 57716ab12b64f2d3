--- strike's S.pace:move beside bump's and slick's world:move: one body moved through a space
--- of 1,000 static boxes (issue: "`space:move` of one body through a 1,000-body space: at
--- least as fast per call as bump's `world:move` (AABBs only) and faster than slick's
--- `world:move`; 0 KB per call with reused results"). Not part of make test. From the
--- repository root, under any VM (`make bench-move` runs LuaJIT and Lua 5.4):
---   luajit bench/move.lua [--moves 10000] [--only strike,strike-shapes,bump,slick] [--save]
---                         [--jit love|stock] [--peer-jit]
--- Libraries (--only): strike (S.trikers.Rectangle colliders in S.pace), strike-shapes (bare
--- S.hapes.Rectangle in S.pace), and the peers found in $STRIKE_PEERS (checkouts named
--- bump.lua and slick, never part of this repository), through bench/adapters/move_*.lua.
--- Missing ones are skipped with a note. LuaJIT runs with LÖVE's JIT limits, as a game does
--- (bench/space.lua's default), or with the standalone interpreter's own with --jit stock. A
--- peer that crashes LuaJIT runs with the JIT off (its adapter's `jitOff`, said in the table:
--- slick, whose moves here crash LuaJIT 2.1.0-beta3 in about one run in three), unless
--- --peer-jit.
--- slick needs setfenv and the global unpack: on Lua 5.2+ its adapter loads it with shims for
--- both (its files unchanged; the same moves and collisions as on Lua 5.1 and LuaJIT).
---
--- The workload, the same numbers for every library (built here, seeded; bench/spaceworld.lua's
--- PRNG, spec/helpers/prng.lua, so the same on every VM):
---   world   1,000 axis-aligned boxes, w and h uniform in 8-24 px, centred uniformly in a
---           square of side 40 sqrt(1000) (about 1,265 px; overlaps between boxes allowed).
---   mover   one 16 x 16 box, moved by its centre. Move k asks for the centre the last move
---           reached plus offset k: a steady drift (DRIFT_X, DRIFT_Y) plus 2-8 px in a uniform
---           direction (a fixed seeded list), so that it runs into boxes and slides along them
---           often. No filter: every library's default response, 'slide'.
---   teleports  (no collision checks: strike body:translateTo, bump world:update, slick
---           world:update) to seeded points where the mover overlaps no box (1 px clear): to
---           spawn point r at moves 1, 1 + RESYNC, 1 + 2 RESYNC ... (the libraries' paths part
---           a little, their contact rules differ, and this brings them back together), and,
---           when a move ends with the centre outside the square, to the next wrap point
---           (instead of the opposite border, which may be inside a box: libraries treat a
---           start inside a box differently). A pass makes the same teleports in every library
---           at the same moves (wraps aside, counted and shown), inside the timed loop (strike's
---           translateTo defers its broadphase update to the next query, the next move; bump
---           and slick update theirs in the call).
--- Measures, per library, each in its own freshly built world (then a full GC and, on LuaJIT,
--- the trace cache flushed):
---   µs per move   one warm-up pass of --moves moves, then 3 timed passes (os.clock around the
---                 whole loop: goal, move, teleports), best and worst of the 3;
---   collisions per move   the count each library's move returns, averaged over a pass (every
---                 pass is the same: it starts from spawn point 1), with the px actually moved
---                 per move and the wraps per pass: the workloads are comparable when these
---                 are of the same order;
---   max overlap   in the warm-up pass, after every move, the deepest overlap of the mover with
---                 any box (brute force; min of the two axes' overlaps), px: 0 when every
---                 move stops at or before the touch;
---   KB per move   1,000 moves (the start of a pass) with the GC stopped, after the timed
---                 passes: collectgarbage('count') after minus before, / 1,000 (on LuaJIT with
---                 the count of traces compiled meanwhile, since a trace is a GC object).
--- Then strike's time over each peer's (below 1: strike faster). --save writes every number
--- to bench/results/move-<vm>.csv (move-luajit-stock.csv with --jit stock; vm,section,library,
--- n,metric,value as space-<vm>.csv).
package.path = './?.lua;./?/init.lua;' .. package.path

local PRNG = require('spec.helpers.prng')
local H = require('bench.harness')
local fmt, tableOut, fullGC = H.fmt, H.tableOut, H.fullGC

local clock = os.clock
local jit = rawget(_G, 'jit')
local sqrt, cos, sin, pi, abs, min, max, huge = math.sqrt, math.cos, math.sin, math.pi, math.abs, math.min, math.max,
  math.huge

local opts = { moves = 10000, only = nil, save = false, jit = nil, peerJit = false }
do
  local list = H.list
  local i = 1
  while arg[i] do
    local a, v = arg[i], arg[i + 1]
    if a == '--moves' then
      opts.moves = tonumber(v)
      if not opts.moves or opts.moves < 1 or opts.moves % 1 ~= 0 then error('--moves must be a positive integer') end
      i = i + 1
    elseif a == '--only' then
      opts.only = {}
      for _, name in ipairs(list(v)) do opts.only[name] = true end
      i = i + 1
    elseif a == '--save' then opts.save = true
    elseif a == '--jit' then opts.jit = v; i = i + 1
    elseif a == '--peer-jit' then opts.peerJit = true
    else error('unknown option ' .. a) end
    i = i + 1
  end
end

-- LuaJIT's limits: LÖVE's by default, as a game runs (LÖVE 11.4's boot.lua raises them:
-- maxtrace 2000, maxrecord 8000, maxmcode 16384 KB), or the standalone interpreter's own
-- with --jit stock.
local JIT_LIMITS = H.jitLimits(opts.jit)

local N = 1000 -- static boxes
local SEED = 20261200 + N
local MOVER_W, MOVER_H = 16, 16
local DRIFT_X, DRIFT_Y = 2.4, 1.1 -- px per move
local STEP_MIN, STEP_MAX = 2, 8 -- the random part of each move, px
local RESYNC = 250 -- moves between spawn teleports
local WRAP_POINTS = 500 -- wrap points, used in turn (then again from the first)
local CLEAR = 1 -- px between a spawn or wrap point's mover and every box
local PASSES, KB_MOVES = 3, 1000

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
  elseif type(S.pace) ~= 'function' or type(S.pace().move) ~= 'function' then
    skipped[#skipped + 1] = 'strike (no S.pace():move in this checkout)'
  else
    local A = require('bench.adapters.move_strike')
    if wanted('strike') then libs[#libs + 1] = A.colliders end
    if wanted('strike-shapes') then libs[#libs + 1] = A.shapes end
  end
end
H.peers({ { 'bump.lua', 'bump', 'bench.adapters.move_bump' },
  { 'slick', 'slick', 'bench.adapters.move_slick' } }, wanted, libs, skipped,
  'bump, slick (set STRIKE_PEERS to a folder with bump.lua and slick checkouts)')

---------------------------------------------------------------------------------------------
-- The workload.

-- The boxes.
local world = { n = N, side = 40 * sqrt(N), x = {}, y = {}, w = {}, h = {}, mw = MOVER_W, mh = MOVER_H }
do
  local rng = PRNG.new(SEED)
  for i = 1, N do
    world.w[i], world.h[i] = rng:range(8, 24), rng:range(8, 24)
    world.x[i], world.y[i] = rng:range(0, world.side), rng:range(0, world.side)
  end
end

-- The deepest overlap of the mover centred on (x, y) with any box (0 when none), px.
local function overlapAt(x, y)
  local bx, by, bw, bh = world.x, world.y, world.w, world.h
  local hw, hh, deepest = MOVER_W / 2, MOVER_H / 2, 0
  for i = 1, N do
    local ox = bw[i] / 2 + hw - abs(x - bx[i])
    if ox > 0 then
      local oy = bh[i] / 2 + hh - abs(y - by[i])
      if oy > 0 then deepest = max(deepest, min(ox, oy)) end
    end
  end
  return deepest
end

-- Is the mover centred on (x, y) at least CLEAR px from every box?
local function clear(x, y)
  local bx, by, bw, bh = world.x, world.y, world.w, world.h
  local hw, hh = MOVER_W / 2 + CLEAR, MOVER_H / 2 + CLEAR
  for i = 1, N do
    if abs(x - bx[i]) < bw[i] / 2 + hw and abs(y - by[i]) < bh[i] / 2 + hh then return false end
  end
  return true
end

-- The moves (offsets ox, oy), the spawn points (sx, sy) and the wrap points (wx, wy).
local plan = { side = world.side, count = opts.moves, ox = {}, oy = {}, sx = {}, sy = {}, wx = {}, wy = {},
  spawns = math.ceil(opts.moves / RESYNC), wraps = WRAP_POINTS }
do
  local rng = PRNG.new(SEED + 1)
  for k = 1, opts.moves do
    local a, d = rng:range(-pi, pi), rng:range(STEP_MIN, STEP_MAX)
    plan.ox[k], plan.oy[k] = DRIFT_X + d * cos(a), DRIFT_Y + d * sin(a)
  end
  local function points(xs, ys, count)
    for j = 1, count do
      local x, y
      repeat
        x, y = rng:range(0, world.side), rng:range(0, world.side)
      until clear(x, y)
      xs[j], ys[j] = x, y
    end
  end
  points(plan.sx, plan.sy, plan.spawns)
  points(plan.wx, plan.wy, plan.wraps)
end
world.startX, world.startY = plan.sx[1], plan.sy[1]

-- One pass: moves 1 .. count of the plan, from spawn point 1. Returns the collisions
-- reported, the wraps, and (with `check`) the px moved and the deepest overlap after a move.
local function pass(st, count, check)
  local move, teleport = st.move, st.teleport
  local ox, oy, side = plan.ox, plan.oy, plan.side
  local sx, sy, wx, wy, nw = plan.sx, plan.sy, plan.wx, plan.wy, plan.wraps
  local x, y = sx[1], sy[1]
  teleport(x, y)
  local cols, wraps, w, r, dist, deepest = 0, 0, 0, 1, 0, 0
  for k = 1, count do
    if k % RESYNC == 1 and k > 1 then
      r = r + 1
      x, y = sx[r], sy[r]
      teleport(x, y)
    end
    local ax, ay, n = move(x + ox[k], y + oy[k])
    cols = cols + n
    if check then
      dist = dist + sqrt((ax - x) ^ 2 + (ay - y) ^ 2)
      deepest = max(deepest, overlapAt(ax, ay))
    end
    x, y = ax, ay
    if x < 0 or x > side or y < 0 or y > side then
      wraps = wraps + 1
      w = w % nw + 1
      x, y = wx[w], wy[w]
      teleport(x, y)
    end
  end
  return cols, wraps, dist, deepest
end

---------------------------------------------------------------------------------------------
-- Running.

-- LuaJIT trace events during the timed passes and the KB moves.
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


-- Every number, for the CSV: library, metric, value.
local csv = {}
local function put(lib, metric, value)
  csv[#csv + 1] = { lib, metric, value }
end

-- Does lib run with the JIT off here?
local function jitOff(lib)
  return jit and lib.jitOff and not opts.peerJit
end

local function run(lib)
  fullGC()
  if jitOff(lib) then jit.off() end
  local t0 = clock()
  local st = lib.new(world)
  local buildMs = (clock() - t0) * 1000
  fullGC()
  if jit then jit.flush() end
  local K = plan.count
  local cols, wraps, dist, deepest = pass(st, K, true)
  fullGC()
  local best, worst = huge, 0
  flushes, aborts, counting = 0, 0, true
  for _ = 1, PASSES do
    local p0 = clock()
    local c, wr = pass(st, K)
    local t = clock() - p0
    best, worst = min(best, t), max(worst, t)
    if c ~= cols or wr ~= wraps then
      error(('pass not repeatable: %d collisions and %d wraps, warm-up %d and %d'):format(c, wr, cols, wraps))
    end
  end
  counting = false
  local fl, ab = flushes, aborts
  local kbMoves = min(KB_MOVES, K)
  fullGC()
  collectgarbage('stop')
  local kb0 = collectgarbage('count')
  traces, counting = 0, true
  pass(st, kbMoves)
  counting = false
  local kb = (collectgarbage('count') - kb0) / kbMoves
  collectgarbage('restart')
  if jitOff(lib) then jit.on() end
  return { lib = lib.name, best = best * 1e6 / K, worst = worst * 1e6 / K, cols = cols / K, dist = dist / K,
    wraps = wraps, deepest = deepest, kb = kb, kbMoves = kbMoves, kbTraces = jit and traces, flushes = jit and fl,
    aborts = jit and ab, build = buildMs, jitOff = jitOff(lib) and true or nil }
end

local t00 = os.time()
note(('strike move bench on %s%s: %d boxes, %d moves a pass'):format(vmName,
  jit and (' (JIT limits: ' .. JIT_LIMITS .. ')') or '', N, plan.count))
local rows = {}
for _, lib in ipairs(libs) do
  local c0 = clock()
  local ok, r = pcall(run, lib)
  if not ok then
    r = { lib = lib.name, err = tostring(r) }
    if jitOff(lib) then jit.on() end
  end
  rows[#rows + 1] = r
  if r.err then note(('  %-13s ERROR: %s'):format(lib.name, r.err))
  else
    note(('  %-13s %8.2f µs/move (worst %.2f) %6.3f collisions/move %8.4f KB/move  %.1f s'):format(lib.name, r.best,
      r.worst, r.cols, r.kb, clock() - c0))
  end
  fullGC()
end

---------------------------------------------------------------------------------------------
-- Tables.

print(('strike move bench — %s%s'):format(vmName, jit and (' (JIT limits: ' .. JIT_LIMITS .. ')') or ''))
for _, l in ipairs(libs) do
  local off = jitOff(l) and '; JIT OFF (it crashes LuaJIT here; --peer-jit: on)' or ''
  print(('  %-13s %s%s'):format(l.name, l.note, off))
end
print()
print(('Move one %dx%d box through %d static boxes 8-24 px in a %.0f px square: %d moves a pass, each '
  .. '(%.1f, %.1f) + %g-%g px in a seeded direction, default slide response; a teleport to a free spawn '
  .. 'point every %d moves and on leaving the square (µs per move, os.clock, best and worst of %d passes '
  .. 'after one)'):format(MOVER_W, MOVER_H, N, world.side, plan.count, DRIFT_X, DRIFT_Y, STEP_MIN, STEP_MAX,
  RESYNC, PASSES))
local body = {}
for _, r in ipairs(rows) do
  if r.err then
    body[#body + 1] = { r.lib, 'ERROR', r.err, '', '', '', '', '', '', '' }
  else
    put(r.lib, 'us_per_move_best', r.best)
    put(r.lib, 'us_per_move_worst', r.worst)
    put(r.lib, 'collisions_per_move', r.cols)
    put(r.lib, 'px_moved_per_move', r.dist)
    put(r.lib, 'wraps_per_pass', r.wraps)
    put(r.lib, 'max_overlap_px', r.deepest)
    put(r.lib, 'kb_per_move_gc_stopped', r.kb)
    put(r.lib, 'build_ms', r.build)
    if r.jitOff then put(r.lib, 'jit_off', 1) end
    if jit then
      put(r.lib, 'trace_flushes', r.flushes)
      put(r.lib, 'trace_aborts', r.aborts)
      put(r.lib, 'traces_in_kb_moves', r.kbTraces)
    end
    body[#body + 1] = { r.lib .. (r.jitOff and ' (JIT off)' or ''), fmt(r.best), fmt(r.worst), fmt(r.cols, 3),
      fmt(r.dist, 2), tostring(r.wraps), ('%.2g'):format(r.deepest),
      fmt(r.kb, 4) .. ((r.kbTraces and r.kbTraces > 0) and (' (%d traces)'):format(r.kbTraces) or ''),
      jit and (r.flushes .. ' / ' .. r.aborts) or '—', fmt(r.build, 1) }
  end
end
tableOut({ 'library', 'µs/move best', 'worst', 'collisions/move', 'px moved/move', 'wraps/pass', 'max overlap px',
  ('KB/move (GC stopped, %d moves)'):format(math.min(KB_MOVES, plan.count)), 'trace flushes / aborts',
  'build ms' }, body)

-- Side by side: strike's time over each peer's.
local strikes, peers = {}, {}
for _, r in ipairs(rows) do
  if not r.err then
    if r.lib:match('^strike') then strikes[#strikes + 1] = r else peers[#peers + 1] = r end
  end
end
if #strikes > 0 and #peers > 0 then
  local head, cells = {}, {}
  for _, s in ipairs(strikes) do
    for _, p in ipairs(peers) do
      local ratio = s.best / p.best
      head[#head + 1] = s.lib .. ' ÷ ' .. p.lib .. (p.jitOff and ' (JIT off)' or '')
      cells[#cells + 1] = ('%.2f×'):format(ratio)
      put(s.lib, 'time_over_' .. p.lib, ratio)
    end
  end
  print('Side by side (best µs per move; strike ÷ peer = strike\'s time over the peer\'s, below 1 = strike faster)')
  tableOut(head, { cells })
end
if jit then
  print('KB/move: (n traces) = n traces were compiled during the measured moves, and a trace is a GC object.')
end
if #skipped > 0 then print('skipped: ' .. table.concat(skipped, '; ')) end
print(('(%d s in all)'):format(os.time() - t00))

if opts.save then
  local path = 'bench/results/move-' .. vmFile .. '.csv'
  local f = assert(io.open(path, 'w'))
  f:write('vm,section,library,n,metric,value\n')
  for _, r in ipairs(csv) do
    f:write(('%s,%s,%s,%d,%s,%.6g\n'):format(vmName .. (jit and (' ' .. JIT_LIMITS) or ''), 'move', r[1], N, r[2],
      r[3]))
  end
  f:close()
  print('saved ' .. path)
end
