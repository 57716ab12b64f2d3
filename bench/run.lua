--- strike's benchmark suite. Run from the repository root:
---   luajit bench/run.lua [--pairs N] [--seed N] [--save] [--only workload] [--full]
--- (--only concave: only the Concave construction table)
--- or `make bench` (LuaJIT and Lua 5.4; BENCH_VMS="lua5.1 ..." for others).
--- Peers: set STRIKE_PEERS to a folder holding checkouts named HC, bump.lua, slick or
--- Strike; each found is run through its adapter in bench/adapters/ (written against its
--- public API) and the table shows strike's speed as a multiple of theirs. Without it,
--- the peers are skipped. Peers are never part of this repository.
---
--- Every number is measured here: calls per second (best of 5 timed runs of about 0.1 s
--- each, after a warm-up and a calibrating run, on a loop compiled fresh for each row) and
--- KB allocated per call (the second of two passes with the GC stopped, JIT on where
--- there is one unless the adapter asks otherwise). A row whose one pass over the pairs
--- takes longer than a run is timed on the first pairs only (at least 500; marked * in
--- the table). Before timing, each library's verdicts are checked against the independent
--- oracle of the property specs; strike's MTV lengths too. A peer's cell shows how many
--- verdicts it got wrong. Every pair is checked, except that a library so slow that
--- building and checking all of a workload's pairs would take over 2 s is built, checked
--- and timed on the first pairs that fit (at least 500; the table says how many); --full
--- lifts that limit.
---
--- A second table times S.trikers.Concave (strike only) on outlines of 1,000 to 10,000
--- vertices, so that the growth of the convex decomposition with the vertex count shows: a
--- random star, a regular star (the worst case found: its middle piece has n / 2 vertices, every
--- face a cut) and a comb; and says whether the slowest build of 10,000 vertices stays under
--- 1 s (issue 21's target, on every VM: BENCH_VMS="lua5.1 lua5.2 lua5.3 lua5.4 luajit").
---
--- Adapter methods: { name, build = function(desc) → object or nil (unsupported),
--- test = function(a, b) → hit, separation length }, and optionally
--- pair = function(a, b) → a', b' (a per-pair scene, e.g. a world holding both, built
--- before timing; test then receives a', b') and jitOff = true (LuaJIT: build, check and
--- time that method with the JIT flushed and off).
package.path = './?.lua;./?/init.lua;' .. package.path

local W = require('bench.workloads')
local H = require('bench.harness')

local clock = os.clock
local jit = rawget(_G, 'jit')

local opts = { pairs = 10000, seed = 42, save = false, full = false }
do
  local i = 1
  while arg[i] do
    local a = arg[i]
    if a == '--pairs' then opts.pairs = tonumber(arg[i + 1]); i = i + 1
    elseif a == '--seed' then opts.seed = tonumber(arg[i + 1]); i = i + 1
    elseif a == '--save' then opts.save = true
    elseif a == '--full' then opts.full = true
    elseif a == '--only' then opts.only = arg[i + 1]; i = i + 1
    else error('unknown option ' .. a) end
    i = i + 1
  end
end

local vmName = jit and jit.version or _VERSION
local vmFile = jit and 'luajit' or _VERSION:gsub('Lua ', 'lua')

-- Libraries: strike first, then the peers found under STRIKE_PEERS.
local libs = { (require('bench.adapters.strike')) } -- one value: Lua 5.4's require returns two
local skipped = {}
H.peers({ { 'HC', 'HC', 'bench.adapters.hc' }, { 'Strike', 'Strike', 'bench.adapters.strike_original' },
  { 'slick', 'slick', 'bench.adapters.slick' }, { 'bump.lua', 'bump.lua', 'bench.adapters.bump' } },
  function() return true end, libs, skipped,
  'HC, Strike, slick, bump.lua (set STRIKE_PEERS to a folder with their checkouts)')

local timeRow, verify, MIN_TIMED = H.timeRow, H.verify, H.MIN_TIMED

local rows = {}
local function record(workload, lib, method, rate, kb, wrongV, wrongD, timed, checked, total)
  rows[#rows + 1] = { workload = workload, lib = lib, method = method, rate = rate, kb = kb,
    wrongV = wrongV, wrongD = wrongD, timed = timed, checked = checked, total = total }
end

local function progress(workload, lib, method, rate, kb, wrongV, wrongD, seconds)
  io.stderr:write(('  %-14s %-8s %-22s %10.0f /s %8.3f KB/call %5.1f s%s\n'):format(workload, lib, method, rate,
    kb, seconds, (wrongV + wrongD > 0) and (' MISMATCHES ' .. wrongV .. '/' .. wrongD) or ''))
end

-- LuaJIT: a method may ask for the JIT off (flushed first, so no trace of it runs).
local function jitOff(method)
  if jit and method.jitOff then jit.flush() jit.off() end
end
local function jitOn(method)
  if jit and method.jitOff then jit.on() end
end

-- Seconds a row may spend building and checking its pairs, unless --full: a library so
-- slow that all the pairs would take longer is built, checked and timed on the first
-- pairs that fit (at least PROBE).
local ROW_BUDGET = 2
local PROBE = 500

-- Build, check and time one method on one workload.
local function runMethod(workload, lib, method, list)
  local c0 = clock()
  local A, B = {}, {}
  local n = #list
  -- Build (and pair) pairs i..j and check them; false when the method does not apply.
  local wrongV, wrongD = 0, 0
  local function take(i, j)
    for k = i, j do
      A[k], B[k] = method.build(list[k][1]), method.build(list[k][2])
      if A[k] == nil or B[k] == nil then return false end
    end
    if method.pair then
      for k = i, j do A[k], B[k] = method.pair(A[k], B[k]) end
    end
    local v, d = verify(lib.name == 'strike', method, list, A, B, i, j)
    wrongV, wrongD = wrongV + v, wrongD + d
    return true
  end
  local used = math.min(n, PROBE)
  if not take(1, used) then return end
  if used < n then
    local perPair = (clock() - c0) / used
    local fit = opts.full and n or 2 * math.floor(ROW_BUDGET / perPair / 2)
    local more = math.min(n, math.max(used, fit))
    if more > used and not take(used + 1, more) then return end
    used = more
  end
  local rate, kb, timed = timeRow(method.test, A, B, used)
  record(workload, lib.name, method.name, rate, kb, wrongV, wrongD, timed, used, n)
  progress(workload, lib.name, method.name .. (used < n and (' [' .. used .. ']') or ''), rate, kb, wrongV, wrongD,
    clock() - c0)
end

local t0 = os.time()
io.stderr:write(('strike bench on %s: %d pairs per workload, seed %d\n'):format(vmName, opts.pairs, opts.seed))
for _, w in ipairs(W.pairWorkloads) do
  if not opts.only or opts.only == w.name then
    local g0 = clock()
    local list = W.generate(w.name, opts.pairs, opts.seed)
    io.stderr:write(('  %-14s generated in %.1f s\n'):format(w.name, clock() - g0))
    for _, lib in ipairs(libs) do
      for _, method in ipairs(lib.methods) do
        jitOff(method)
        runMethod(w.name, lib, method, list)
        jitOn(method)
        collectgarbage('collect')
      end
    end
  end
end

-- Transforms: one body moved, turned and bounded per call.
if not opts.only or opts.only == 'transforms' then
  local bodies = W.bodies(1000, opts.seed)
  for _, lib in ipairs(libs) do
    local t = lib.transform
    if t then
      local c0 = clock()
      local A, B = {}, {}
      for i, d in ipairs(bodies) do A[i] = t.build(d) end
      local step = t.step
      local rate, kb, timed = timeRow(function(s) step(s) end, A, B, #A)
      record('transforms', lib.name, 'move+turn+bbox', rate, kb, 0, 0, timed, #A, #A)
      progress('transforms', lib.name, 'move+turn+bbox', rate, kb, 0, 0, clock() - c0)
    end
  end
end

-- Concave construction: S.trikers.Concave from outlines of growing size (validation,
-- triangulation, merging and the pieces' ConvexPolygons), best of CONCAVE_RUNS builds per
-- size, so that the growth with the vertex count shows. Each collider's area is checked
-- against the outline's (shoelace). About 3-5 s in all per VM.
local CONCAVE_SIZES, CONCAVE_RUNS = { 1000, 2000, 5000, 10000 }, 3
local CONCAVE_KINDS = {
  { 'star', 'random star (random radius 0.2-1 per vertex, sorted angles)' },
  { 'regular', 'regular star (n/2 spikes, radii 1 and 0.5)' },
  { 'comb', 'comb (n/4 rectangular teeth)' },
}
local concave = {} -- concave[kind][n] = { seconds =, kb =, pieces =, ok = }
if not opts.only or opts.only == 'concave' then
  local S = require('strike')
  for _, k in ipairs(CONCAVE_KINDS) do
    local c0 = clock()
    concave[k[1]] = {}
    for _, n in ipairs(CONCAVE_SIZES) do
      local v = W.outline(k[1], n, opts.seed)
      local area = 0
      for i = 1, n do
        local j = i % n + 1
        area = area + v[2 * i - 1] * v[2 * j] - v[2 * j - 1] * v[2 * i]
      end
      area = math.abs(area) / 2
      local best, c = math.huge, nil
      for _ = 1, CONCAVE_RUNS do
        collectgarbage('collect')
        local b0 = clock()
        c = S.trikers.Concave(v)
        best = math.min(best, clock() - b0)
      end
      collectgarbage('collect')
      collectgarbage('stop')
      local before = collectgarbage('count')
      S.trikers.Concave(v)
      local kb = collectgarbage('count') - before
      collectgarbage('restart')
      local ok = math.abs(c:getArea() - area) <= 1e-9 * area
      concave[k[1]][n] = { seconds = best, kb = kb, pieces = c:getShapeCount(), ok = ok }
      -- in the CSV: builds per second and KB per build; wrong_verdicts 1 when the area is off
      record('concave-' .. k[1] .. '-' .. n, 'strike', 'S.trikers.Concave', 1 / best, kb, ok and 0 or 1, 0, 1, 1, 1)
    end
    io.stderr:write(('  %-14s %-8s %-22s %.1f s\n'):format('concave-' .. k[1], 'strike', 'S.trikers.Concave',
      clock() - c0))
  end
end

-- The table: one line per workload, strike's methods, then one column pair per peer
-- method: its speed, and strike's speed as a multiple of it (against strike's method of
-- the same name, else S.AT, else S.triking). A peer's verdicts that disagree with the
-- oracle are counted in its cell.
local subset = false
local function fmtRate(r)
  if not r then return '—' end
  local cell = (r.rate >= 1e4 and '%.0fk' or '%.1fk'):format(r.rate / 1000)
  if r.timed < r.total then
    subset = true
    cell = cell .. '*'
  end
  return cell
end
-- A peer's verdicts: '(15 wrong)', or on a prefix '(15/3000 wrong)', '(3000 checked)'.
local function fmtChecked(r)
  if r.checked < r.total then
    subset = true
    if r.wrongV > 0 then return (' (%d/%d wrong)'):format(r.wrongV, r.checked) end
    return (' (%d checked)'):format(r.checked)
  end
  if r.wrongV > 0 then return (' (%d wrong)'):format(r.wrongV) end
  return ''
end
local function find(workload, lib, method)
  for _, r in ipairs(rows) do
    if r.workload == workload and r.lib == lib and (not method or r.method == method) then return r end
  end
end

local names = {}
for _, w in ipairs(W.pairWorkloads) do names[#names + 1] = w.name end
names[#names + 1] = 'transforms'

local columns = {} -- peer methods: { lib =, method =, first = true for a library's first method, label = }
for i = 2, #libs do
  local lib = libs[i]
  for k, m in ipairs(lib.methods) do
    columns[#columns + 1] = { lib = lib.name, method = m.name, first = k == 1,
      label = #lib.methods > 1 and (lib.name .. ' ' .. m.name) or lib.name }
  end
end

local header = { 'workload', 'S.AT/s', 'KB/call', 'S.triking/s', 'KB/call', 'ok' }
for _, c in ipairs(columns) do
  header[#header + 1] = c.label .. '/s'
  header[#header + 1] = 'strike÷' .. c.label
end
print(('strike bench — %s — %d pairs per workload, seed %d'):format(vmName, opts.pairs, opts.seed))
local anyPairs = false -- (none with --only concave)
for _, name in ipairs(names) do anyPairs = anyPairs or find(name, 'strike') ~= nil end
if anyPairs then
  print('| ' .. table.concat(header, ' | ') .. ' |')
  local sep = {}
  for i = 1, #header do sep[i] = '---' end
  print('|' .. table.concat(sep, '|') .. '|')
end
for _, name in ipairs(names) do
  local at = find(name, 'strike', 'S.AT') or find(name, 'strike', 'move+turn+bbox')
  local tr = find(name, 'strike', 'S.triking')
  if at or tr then
    local okCell = 'yes'
    for _, r in ipairs(rows) do
      if r.workload == name and r.lib == 'strike' then
        if r.wrongV + r.wrongD > 0 then okCell = 'NO' end
        if okCell == 'yes' and r.checked < r.total then okCell = ('yes (%d checked)'):format(r.checked) end
      end
    end
    local cells = { name, fmtRate(at), at and ('%.3f'):format(at.kb) or '—',
      fmtRate(tr), tr and ('%.3f'):format(tr.kb) or '—', okCell }
    for _, c in ipairs(columns) do
      local r = find(name, c.lib, c.method)
      if not r and c.first and name == 'transforms' then r = find(name, c.lib, 'move+turn+bbox') end
      local mine = find(name, 'strike', r and r.method) or at or tr
      local cell = fmtRate(r)
      if r then cell = cell .. fmtChecked(r) end
      cells[#cells + 1] = cell
      cells[#cells + 1] = r and ('%.1f×'):format(mine.rate / r.rate) or '—'
    end
    print('| ' .. table.concat(cells, ' | ') .. ' |')
  end
end
if subset then
  print(('* timed on the first pairs only (at least %d). A library too slow to build and check every pair '
    .. 'in %g s per row is checked on the first pairs that fit (counts in brackets); --full checks all.')
    :format(MIN_TIMED, ROW_BUDGET))
end
if concave[CONCAVE_KINDS[1][1]] then
  if anyPairs then print() end
  local head = { 'Concave construction (ms, best of ' .. CONCAVE_RUNS .. ')' }
  for _, n in ipairs(CONCAVE_SIZES) do head[#head + 1] = ('%d vertices'):format(n) end
  head[#head + 1] = ('pieces at %d'):format(CONCAVE_SIZES[#CONCAVE_SIZES])
  head[#head + 1] = ('MB allocated at %d'):format(CONCAVE_SIZES[#CONCAVE_SIZES])
  head[#head + 1] = 'ok'
  print('| ' .. table.concat(head, ' | ') .. ' |')
  local line = {}
  for i = 1, #head do line[i] = '---' end
  print('|' .. table.concat(line, '|') .. '|')
  for _, k in ipairs(CONCAVE_KINDS) do
    local cells, ok = { k[2] }, 'yes'
    for _, n in ipairs(CONCAVE_SIZES) do
      local r = concave[k[1]][n]
      cells[#cells + 1] = ('%.1f'):format(r.seconds * 1000)
      if not r.ok then ok = 'NO (area)' end
    end
    local last = concave[k[1]][CONCAVE_SIZES[#CONCAVE_SIZES]]
    cells[#cells + 1] = tostring(last.pieces)
    cells[#cells + 1] = ('%.1f'):format(last.kb / 1024)
    cells[#cells + 1] = ok
    print('| ' .. table.concat(cells, ' | ') .. ' |')
  end
  local largest, slowest, which = CONCAVE_SIZES[#CONCAVE_SIZES], 0, nil
  for _, k in ipairs(CONCAVE_KINDS) do
    local r = concave[k[1]][largest]
    if r.seconds > slowest then slowest, which = r.seconds, k[1] end
  end
  print(('Slowest at %d vertices: %.0f ms (%s); target (issue 21): under 1,000 ms on every VM, %s'):format(largest,
    slowest * 1000, which, slowest < 1 and 'met' or 'NOT MET'))
end
if #skipped > 0 then print('peers skipped: ' .. table.concat(skipped, '; ')) end
print(('(%d s in all)'):format(os.time() - t0))

if opts.save then
  local path = 'bench/results/' .. vmFile .. '.csv'
  local f = assert(io.open(path, 'w'))
  f:write('vm,workload,library,method,calls_per_s,kb_per_call,wrong_verdicts,wrong_depths,pairs,checked_pairs,'
    .. 'timed_pairs\n')
  for _, r in ipairs(rows) do
    f:write(('%s,%s,%s,%s,%.0f,%.4f,%d,%d,%d,%d,%d\n'):format(vmName, r.workload, r.lib, r.method, r.rate, r.kb,
      r.wrongV, r.wrongD, r.total, r.checked, r.timed))
  end
  f:close()
  print('saved ' .. path)
end
