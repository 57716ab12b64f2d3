--- The narrow phase beside Box2D, inside LÖVE, side by side (issue 21, target 5: at 10,000
--- pairs, strike at 0.5 times Box2D's pairs per second or more, polygons and circle-polygon).
--- Not part of make test. From the repository root, under any VM (the timing happens in LÖVE,
--- under LÖVE's LuaJIT, whatever the VM here); `make bench` runs it once when `love` is on
--- the PATH, `make bench-narrow` alone:
---   luajit bench/narrow.lua [--pairs 10000] [--seed 42] [--workloads poly-poly,circle-poly] [--save]
--- It runs the LÖVE program bench/lovephysics with --section narrow, which times, in one
--- process, strike's S.AT and S.triking on bench/run.lua's pair workloads (the same seeded
--- pairs) and Box2D's contact update on the same pairs in a love.physics world, and prints a
--- line per result; this reads them and prints the tables. What each Box2D figure counts is
--- written at narrow() in bench/lovephysics/main.lua; in short, Box2D's rate lies between
---   the lower bound  a world step's cost per contact over all the pairs: the manifold, the
---                    contact loop's bookkeeping and, for each touching contact, the contact
---                    solver's setup (no velocity or position iteration);
---   the upper bound  the same over the pairs Box2D finds apart: a manifold of no points, no
---                    solver; a touching pair's manifold costs at least that;
--- and Box2D's sensors (b2TestOverlap, a yes or no without a manifold) are shown beside.
--- Target 5 is met when S.AT reaches half the upper bound, not met when it stays under half
--- the lower bound, and undecided between.
--- --save writes every number to bench/results/narrow-love.csv. Fails (exit status 1, after
--- the tables) when the LÖVE program fails, when strike's verdicts or MTV lengths disagree
--- with the workload's oracle, or when Box2D's world is not what the measure needs (a contact
--- missing or too many, a contact in the world of pairs apart, a body moved).
package.path = './?.lua;./?/init.lua;' .. package.path

local H = require('bench.harness')

local opts = { pairs = 10000, seed = 42, workloads = 'poly-poly,circle-poly', save = false }
do
  local i = 1
  while arg[i] do
    local a, v = arg[i], arg[i + 1]
    if a == '--pairs' then opts.pairs = tonumber(v); i = i + 1
    elseif a == '--seed' then opts.seed = tonumber(v); i = i + 1
    elseif a == '--workloads' then opts.workloads = v; i = i + 1
    elseif a == '--save' then opts.save = true
    else error('unknown option ' .. a) end
    i = i + 1
  end
end

if not H.loveOnPath() then
  print('narrow phase beside Box2D: skipped (no love on the PATH)')
  return
end

local t0 = os.time()
io.stderr:write(('narrow phase beside Box2D in LÖVE: %d pairs per workload, seed %d (about 20 s)\n')
  :format(opts.pairs, opts.seed))
local recs, err = H.runLove(('--section narrow --pairs %d --seed %d --workloads %s'):format(opts.pairs, opts.seed,
  opts.workloads))
if not recs then
  print('narrow phase beside Box2D: FAILED: ' .. tostring(err))
  os.exit(1)
end

local function find(workload, lib, set, what)
  for _, r in ipairs(recs) do
    if r.kind == 'narrow' and r.workload == workload and r.lib == lib and r.set == set
      and (r.method == what or r.variant == what) then return r end
  end
end

local function k(rate)
  if not rate then return '—' end
  return ('%.0fk'):format(rate / 1000)
end
local function ratio(x) return ('%.2f'):format(x) end

local failed = {}
local workloads = H.list(opts.workloads)

print(('strike narrow phase beside Box2D (love.physics), in one LÖVE process (%s) — %d pairs per workload, seed %d')
  :format(tostring(recs.version), opts.pairs, opts.seed))
print('pairs per second (k/s): strike best of 5 timed runs (bench/run.lua\'s loop); Box2D (world step with the '
  .. 'pairs - world step with them apart) / pairs, best of 25 samples of each')
print()
local head = { 'workload', 'strike S.AT', 'S.triking', 'Box2D lower bound (solver setup counted)',
  'Box2D upper bound (pairs it finds apart)', 'Box2D sensors (b2TestOverlap)', 'S.AT ÷ Box2D',
  'target 5 (≥ 0.5)' }
local rows = {}
for _, w in ipairs(workloads) do
  local at, tr = find(w, 'strike', 'all', 'S.AT'), find(w, 'strike', 'all', 'S.triking')
  local lo, hi, sensor = find(w, 'box2d', 'all', 'solid'), find(w, 'box2d', 'clear', 'solid'),
    find(w, 'box2d', 'all', 'sensor')
  local cells = { w, k(at and at.rate), k(tr and tr.rate), k(lo and lo.rate), k(hi and hi.rate),
    k(sensor and sensor.rate), '—', '—' }
  if at and lo and hi then
    local rLo, rHi = at.rate / hi.rate, at.rate / lo.rate
    cells[7] = ratio(rLo) .. '–' .. ratio(rHi)
    cells[8] = rLo >= 0.5 and 'met' or rHi < 0.5 and 'not met' or 'undecided'
    if opts.pairs ~= 10000 then cells[8] = '(' .. cells[8] .. ': the target is at 10,000 pairs)' end
  else
    failed[#failed + 1] = w .. ': results missing'
  end
  rows[#rows + 1] = cells
end
H.tableOut(head, rows)

print('By set of pairs: all; the overlapping ones (hits); the others that Box2D finds apart too (clear: Box2D\'s '
  .. 'skin, 0.01 m a polygon, makes some of the oracle\'s misses touch)')
head = { 'workload', 'pairs', 'count', 'strike S.AT', 'S.triking', 'Box2D', 'what Box2D\'s figure counts',
  'S.AT ÷ Box2D', 'Box2D ms a step (with the pairs / apart)', 'Box2D touching (oracle disagrees)' }
rows = {}
local counts = {
  solid = 'manifold, contact loop, solver setup of the touching',
  clear = 'manifold (no points), contact loop',
  sensor = 'b2TestOverlap, contact loop (no manifold)',
}
for _, w in ipairs(workloads) do
  for _, v in ipairs({ { 'all', 'solid' }, { 'hits', 'solid' }, { 'clear', 'solid' }, { 'all', 'sensor' } }) do
    local set, variant = v[1], v[2]
    local b = find(w, 'box2d', set, variant)
    local at = variant == 'solid' and find(w, 'strike', set, 'S.AT') or nil
    local tr = variant == 'solid' and find(w, 'strike', set, 'S.triking') or nil
    if b then
      rows[#rows + 1] = { w, set .. (variant == 'sensor' and ' (sensors)' or ''), tostring(b.pairs),
        k(at and at.rate), k(tr and tr.rate), k(b.rate),
        counts[set == 'clear' and 'clear' or variant], at and ratio(at.rate / b.rate) or '—',
        ('%.2f / %.2f'):format(b.together, b.apart), ('%d (%d)'):format(b.touching, b.wrong) }
      if b.rate <= 0 then
        failed[#failed + 1] = ('%s %s %s: the world with the pairs stepped no slower than the one without (%.3f, '
          .. '%.3f ms): too noisy to measure'):format(w, set, variant, b.together, b.apart)
      end
      if b.contacts ~= b.pairs or b.missing ~= 0 or b.extra ~= 0 or b.apart_contacts ~= 0 or b.moved ~= 0 then
        failed[#failed + 1] = ('%s %s %s: %d contacts for %d pairs (%d missing, %d extra), %d apart, %d moved')
          :format(w, set, variant, b.contacts, b.pairs, b.missing, b.extra, b.apart_contacts, b.moved)
      end
    else
      failed[#failed + 1] = ('%s %s %s: no Box2D result'):format(w, set, variant)
    end
    if variant == 'solid' and not (at and tr) then failed[#failed + 1] = ('%s %s: no strike result'):format(w, set) end
    for _, r in ipairs({ at, tr }) do
      if r.wrong ~= 0 or r.depths ~= 0 then
        failed[#failed + 1] = ('%s %s %s: %d wrong verdicts, %d wrong MTV lengths'):format(w, set, r.method, r.wrong,
          r.depths)
      end
    end
  end
end
H.tableOut(head, rows)

print('strike\'s verdicts and MTV lengths: checked against the oracle before timing, '
  .. (#failed == 0 and 'all right' or 'see below'))
print('Box2D: a contact for each pair, none with the pairs apart, no body moved by the steps: '
  .. (#failed == 0 and 'yes' or 'see below'))
print(('(%d s in all)'):format(os.time() - t0))

if opts.save then
  local path = 'bench/results/narrow-love.csv'
  local f = assert(io.open(path, 'w'))
  f:write('workload,set,library,method,pairs,pairs_per_s,kb_per_call,step_ms_together,step_ms_apart,touching,'
    .. 'wrong_verdicts\n')
  for _, r in ipairs(recs) do
    if r.kind == 'narrow' then
      f:write(('%s,%s,%s,%s,%d,%.0f,%s,%s,%s,%s,%d\n'):format(r.workload, r.set, r.lib, r.method or r.variant,
        r.pairs, r.rate, r.kb and ('%.4f'):format(r.kb) or '', r.together and ('%.5f'):format(r.together) or '',
        r.apart and ('%.5f'):format(r.apart) or '', r.touching and tostring(r.touching) or '', r.wrong))
    end
  end
  f:close()
  print('saved ' .. path)
end
if #failed > 0 then
  print('FAILED: ' .. table.concat(failed, '; '))
  os.exit(1)
end
