--- What the bench scripts share (bench/run.lua, move.lua, movers.lua, space.lua, narrow.lua,
--- broadphase.lua, tiled.lua, and the LÖVE program bench/lovephysics): LuaJIT's limits, a full
--- collection, option lists, numbers and markdown tables, the pair tests' timing loop, and
--- running the LÖVE program. Not part of strike.
local H = {}

local clock = os.clock
local load = loadstring or load -- luacheck: ignore 113

--- LuaJIT's limits for a run: 'love' (the default: LÖVE 11.4's boot.lua raises them to
--- maxtrace 2000, maxrecord 8000, maxmcode 16384 KB, as a game runs) or 'stock' (the
--- standalone interpreter's own: 1,000 traces, 512 KB). Sets them and returns which; 'stock'
--- where there is no JIT.
---@param choice string|nil 'love', 'stock' or nil (love)
---@return string
function H.jitLimits(choice)
  if choice ~= nil and choice ~= 'love' and choice ~= 'stock' then error('--jit must be love or stock', 2) end
  if rawget(_G, 'jit') and choice ~= 'stock' then
    require('jit.opt').start('maxtrace=2000', 'maxrecord=8000', 'maxmcode=16384')
    return 'love'
  end
  return 'stock'
end

--- Collect all garbage (twice: finalizers run in the first).
function H.fullGC()
  collectgarbage('collect')
  collectgarbage('collect')
end

--- A comma-separated option's values, numbers as numbers.
---@param s string
---@return table
function H.list(s)
  local t = {}
  for v in s:gmatch('[^,]+') do t[#t + 1] = tonumber(v) or v end
  return t
end

--- x with d decimals (2 by default); '—' for nil, 'nan' for NaN.
---@param x number|nil
---@param d integer|nil
---@return string
function H.fmt(x, d)
  if x == nil then return '—' end
  if x ~= x then return 'nan' end
  return ('%.' .. (d or 2) .. 'f'):format(x)
end

--- Print a markdown table: its head, then each row (a list of cells), then a blank line.
---@param head string[]
---@param rows table[]
function H.tableOut(head, rows)
  print('| ' .. table.concat(head, ' | ') .. ' |')
  local sep = {}
  for i = 1, #head do sep[i] = '---' end
  print('|' .. table.concat(sep, '|') .. '|')
  for _, r in ipairs(rows) do print('| ' .. table.concat(r, ' | ') .. ' |') end
  print()
end

--- Load the peers found in $STRIKE_PEERS: for each { folder, name, adapter module } of `list`
--- that `wanted(name)` allows, the adapter, loaded from the checkout of that folder (a folder
--- with a README.md), is appended to `libs`; one missing or failing is noted in `skipped`, and
--- without STRIKE_PEERS, `hint` is.
---@param list table[]
---@param wanted fun(name: string): boolean
---@param libs table
---@param skipped string[]
---@param hint string
function H.peers(list, wanted, libs, skipped, hint)
  local peerDir = os.getenv('STRIKE_PEERS')
  if not peerDir or peerDir == '' then
    skipped[#skipped + 1] = hint
    return
  end
  for _, p in ipairs(list) do
    if wanted(p[2]) then
      local f = io.open(peerDir .. '/' .. p[1] .. '/README.md', 'r')
      if f then
        f:close()
        local okReq, adapter = pcall(require, p[3])
        local ok, err = false, adapter
        if okReq then ok, err = adapter.load(peerDir, p[1]) end
        if ok then libs[#libs + 1] = adapter else skipped[#skipped + 1] = p[2] .. ' (' .. tostring(err) .. ')' end
      else
        skipped[#skipped + 1] = p[2] .. ' (no ' .. peerDir .. '/' .. p[1] .. ')'
      end
    end
  end
end

-- A fresh copy of the timing loop per row, so that LuaJIT traces one loop per method.
local RUNNER = [[
local test, A, B, n, reps = ...
for _ = 1, reps do
  for i = 1, n do test(A[i], B[i]) end
end
]]

-- Seconds per timed run, and timed runs per row (the best counts: on a shared virtual
-- machine the slow runs are other tenants' doing). A row costs a warm-up, one calibrating
-- run and RUNS timed runs.
local TARGET, RUNS = 0.1, 5
--- Slow rows are timed on a prefix of their pairs (all of them are still checked): at
--- least this many (an even count, so that hits and misses stay balanced).
H.MIN_TIMED = 500

--- A pair test's speed: `test(A[i], B[i])` for i = 1..n, in calls per second (best of 5 timed
--- runs of about 0.1 s each, after a warm-up and a calibrating run, on a loop compiled fresh
--- for each call), KB allocated per call (the second of two passes with the GC stopped), and
--- how many pairs were timed (a row whose one pass takes longer than 0.3 s is timed on the
--- first pairs only, at least H.MIN_TIMED). bench/run.lua's rows and bench/lovephysics's
--- strike rows.
---@param test fun(a: any, b: any)
---@param A any[]
---@param B any[]
---@param n integer
---@return number rate
---@return number kb
---@return integer timed
function H.timeRow(test, A, B, n)
  local run = load(RUNNER)
  local w = math.min(n, H.MIN_TIMED)
  local t0 = clock()
  run(test, A, B, w, 1) -- warm-up, and a first guess at the speed
  local per = math.max(clock() - t0, 1e-6) / w
  local m = n
  if per * n > 3 * TARGET then m = math.min(n, math.max(H.MIN_TIMED, 2 * math.floor(TARGET / per / 2))) end
  local reps = math.max(1, math.floor(TARGET / (per * m) + 0.5))
  local best, runs = math.huge, -1 -- the first run only calibrates
  while runs < RUNS do
    t0 = clock()
    run(test, A, B, m, reps)
    local t = clock() - t0
    if t < TARGET / 2 then
      reps = math.max(reps + 1, math.floor(reps * TARGET / math.max(t, 1e-6) + 0.5))
    else
      if runs >= 0 and t < best then best = t end
      runs = runs + 1
    end
  end
  -- Allocation: the second of two passes with the GC stopped (a full collection shrinks
  -- the stack on some VMs, and the first pass grows it again).
  collectgarbage('collect')
  collectgarbage('stop')
  run(test, A, B, m, 1)
  local before = collectgarbage('count')
  run(test, A, B, m, 1)
  local kb = (collectgarbage('count') - before) / m
  collectgarbage('restart')
  return m * reps / best, kb, m
end

--- A method's verdicts (and, for strike, MTV lengths within 1e-9 relative) against the
--- workload's oracle on pairs i..j: how many verdicts and how many lengths disagree.
---@param isStrike boolean
---@param method table { test = fun(a, b): boolean, number }
---@param pairsList table[] bench/workloads.lua's pairs ({ descA, descB, hit =, depth = })
---@param A any[]
---@param B any[]
---@param i integer
---@param j integer
---@return integer wrongVerdicts
---@return integer wrongDepths
function H.verify(isStrike, method, pairsList, A, B, i, j)
  local wrongVerdict, wrongDepth = 0, 0
  for k = i, j do
    local hit, len = method.test(A[k], B[k])
    if hit ~= pairsList[k].hit then wrongVerdict = wrongVerdict + 1 end
    if isStrike and hit and pairsList[k].depth then
      local want = pairsList[k].depth
      if math.abs(len - want) > 1e-9 * math.max(1, want) then wrongDepth = wrongDepth + 1 end
    end
  end
  return wrongVerdict, wrongDepth
end

--- Is `love` on the PATH?
---@return boolean
function H.loveOnPath()
  local p = io.popen('command -v love 2>/dev/null')
  local path = p and p:read('*l')
  if p then p:close() end
  return path ~= nil and path ~= ''
end

--- Run the LÖVE program bench/lovephysics with `args` (from the repository root); its
--- `box2d <kind> key=value ...` lines as records { kind =, key = value ... } (numbers
--- converted; a `box2d rayhit <ray> <body> <distance>` line as { kind = 'rayhit', ray =,
--- body =, d = }; the `box2d version ...` line's text in the list's field `version`), or nil
--- and the reason. When LÖVE does not start (no `box2d version` line),
--- tries once more under xvfb-run.
---@param args string
---@return table[]|nil records
---@return string|nil why
function H.runLove(args)
  local function try(prefix)
    local p = io.popen(prefix .. 'love bench/lovephysics ' .. args .. ' 2>&1')
    if not p then return nil, 'io.popen failed', false end
    local recs, other, err, started = {}, {}, nil, false
    for line in p:lines() do
      local kind, rest = line:match('^box2d (%S+)%s*(.*)$')
      if kind == 'rayhit' then
        local k, i, d = rest:match('^(%d+) (%d+) (%S+)$')
        recs[#recs + 1] = { kind = kind, ray = tonumber(k), body = tonumber(i), d = tonumber(d) }
      elseif kind == 'error' then
        err = 'LÖVE program: ' .. rest
      elseif kind == 'version' then
        started = true
        recs.version = rest
      elseif kind then
        local r = { kind = kind }
        for key, v in rest:gmatch('([%w_]+)=(%S+)') do r[key] = tonumber(v) or v end
        recs[#recs + 1] = r
      else
        other[#other + 1] = line
      end
    end
    p:close()
    if err then return nil, err, started end
    if #recs == 0 then return nil, table.concat(other, ' / '), started end
    return recs, nil, started
  end
  local recs, err, started = try('')
  if not started then
    local p = io.popen('command -v xvfb-run 2>/dev/null')
    local xvfb = p and p:read('*l')
    if p then p:close() end
    if xvfb and xvfb ~= '' then
      local recs2, err2 = try('xvfb-run -a ')
      if recs2 then return recs2 end
      err = err .. ' / under xvfb-run: ' .. tostring(err2)
    end
  end
  return recs, err
end

return H
