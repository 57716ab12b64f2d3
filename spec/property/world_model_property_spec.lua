-- A model-based spec of the whole world (issue 20, item 1): seeded random programs over the
-- public API of S.pace, every call checked when it returns against a model written in
-- spec/property/world_model.lua over the per-body API (S.triking, containsPoint,
-- body:rayCast, S.weep, S.ite) and a model of begin/stay/end.
--
-- A program: a space of 5-40 bodies of every kind (spec/property/space_world.lua), then
-- steps: a change (add, remove, set, a transform of a body or of a nested member, a member
-- added or removed, a body placed exactly against another, setFilter, on, off, addResponse),
-- a query (collisions, check, queryPoint, queryRect, queryShape, rayCast, rayCastAll, cast,
-- move, bodies/count/has/get), or -- in about half the steps -- a change and at once a query
-- aimed at it, with nothing in between (a wall moved onto a ray, then rayCast). Queries run
-- with out tables kept and reused across calls, some pre-filled with junk. Filters, pair
-- filters, move filters, responses and event callbacks are scripts that query, add, remove,
-- move, set, call on/off (of themselves, of later callbacks) and setFilter, make bad calls,
-- and raise errors, which the program's pcall catches; then the space must still agree with
-- the model, and the events stay balanced. At the end of each program, nothing the program
-- let go may be kept alive by the space. Each program leans toward some of the chains the
-- random mix reaches in few programs (by the bits of its index: world_model.lua, LEAN_WEIGHTS):
-- an error in a callback with others after it on the same event, the pair filter raising,
-- removing or calling collisions(), walks with snap along a floor, a filter moving the body
-- being moved, calls out of the range of motion.
--
-- Replay: a run goes through every program and lists each distinct failure once (how many
-- programs, the first one) and the first in full: the seed and the program (STRIKE_SEED=<seed>
-- STRIKE_PROGRAM=<n>, any VM) and the last calls, indented where they ran inside another
-- (STRIKE_HISTORY=<n> shows more, STRIKE_TRACE=1 adds every call of a filter). Each class of
-- generated operation can be switched off in FEATURES below or with STRIKE_FEATURES (to look
-- past a failure for the next one); everything is on in the committed spec but what a bug of
-- the library turned off: such a switch names the bug, with its reproduction, and goes back on
-- when the library is fixed.
local WM = require('spec.property.world_model')
local PRNG = require('spec.helpers.prng')
local budget = require('spec.helpers.budget')

local FEATURES = {
  pairs = true,        -- a change and at once a query aimed at it
  events = true,       -- programs with callbacks (the recorder and scripted ones)
  responses = true,    -- addResponse: 'stopper' and 'passer', answered by move filters
  junk = true,         -- out tables pre-filled with junk
  holeyJunk = true,    -- junk after a hole (a nil) in an out table
  swapOuts = true,     -- one query's out table passed to another
  crowd = true,        -- every 10th program: a bullet with 'cross' through a row of 66-90 coins
  gc = true,           -- removed bodies and dropped functions must not be kept alive
  touchProbe = true,   -- scripts may change the body a query asks about (check(b), queryShape(b), cast(b))
  -- 'caught' actions in callbacks and pair filters: a query whose filter raises an error that
  -- the game's code run by collisions() catches (found: collisions() returned one level deep,
  -- keeping the filter alive)
  caughtInCollisions = true,
  -- 'caught' actions that rayCast and cast: an error the game's code around them catches
  -- (found: the level kept the filter and the body cast alive)
  levelsLetGo = true,
  -- the end-of-program check covers a level's hit list, one-leaf lists and step probe and a
  -- move level's hit (found: a move that an error stopped after a hit kept the body hit alive;
  -- spec/space_call_order_spec.lua has the repro)
  errorScratchLetsGo = true,
  -- the end-of-program check covers the shapes a colliding pair's record keeps of its earlier
  -- contacts (found: a member removed from a collider stayed alive in the record of a pair of
  -- that collider that went on touching, in rec._sa, rec._sb and S.ite's spare points,
  -- rec._c._spares; seed 79's program 333 on LuaJIT; spec/space_call_order_spec.lua has the
  -- repro)
  contactShapesLetGo = true,
  strictRemoved = true, -- a body removed during a call never appears in its results (else: may)
  memberProbes = true, -- cast() of a member of a body in the space (check and queryShape of one always)
  -- a filter of a cast removes a member (Collider:remove) of the body being cast: the error of
  -- a filter that moved it (found: the cast failed inside strike/motion/sweep.lua, "attempt to
  -- index local 'A' (a nil value)"; space:move too; seed 404's run; the repro is in
  -- spec/space_call_order_spec.lua)
  memberRemovedFromCast = true,
  -- check: a move never meets the same body at t = 0 eight legs in a row without moving
  -- (found: 19 legs from the same place, at 738 units from the origin; the repro is in
  -- spec/space_call_order_spec.lua)
  stuck = true,
  scripts = true,      -- scripts have actions (without it: pure filters and callbacks)
  -- the actions of the scripts (each also by context: <action>In<QueryFilter|PairFilter|
  -- MoveFilter|Callback|Response> = false switches it off there only)
  query = true, collisions = true, remove = true, add = true, transform = true, spaceMove = true, member = true,
  set = true, setFilter = true, on = true, off = true, raise = true, badCall = true, caught = true,
  moveSubject = true, -- (a move's or cast's filter moves the body being moved: an error, docs/space.md)
  -- changes = { transform = false, ... } and queries = { move = false, ... } switch steps off
}

-- STRIKE_FEATURES="gc=false,removeInPairFilter=false,q.bodies=false" switches features for a
-- run (q.<query> and c.<change>: that kind of step).
for item in (os.getenv('STRIKE_FEATURES') or ''):gmatch('[^,%s]+') do
  local k, v = item:match('^([%w_%.]+)=(%w+)$')
  local group, name = (k or ''):match('^([qc])%.(%w+)$')
  if group then
    local t = group == 'q' and 'queries' or 'changes'
    FEATURES[t] = FEATURES[t] or {}
    FEATURES[t][name] = v == 'true'
  elseif k then
    FEATURES[k] = v == 'true'
  end
end

local SEED = PRNG.seedFromEnv(20260521)
local ONLY = tonumber(os.getenv('STRIKE_PROGRAM') or '')
-- 21,600 steps on LuaJIT (a change and a query aimed at it count as two); the first quarter of
-- the programs on Lua 5.1-5.4 (spec/helpers/budget.lua): 43,200 steps per make test
local PROGRAMS, STEPS = budget.cases(360), 60

local stats = {}

-- The kind of a failure: its message without the call's arguments, numbers and body names
-- (so that one run lists each distinct failure once, with the first program that found it);
-- for something kept alive, the first fields of the path that keeps it.
local function signature(msg)
  local main = msg:match('%(rerun: [^)]*%): ([^\n]*)') or msg:match('[^\n]*')
  local kept, path = main:match('^the space keeps %d+ (.-) alive.*: (space.*)$')
  if kept then
    local parts = {}
    for part in (path:gsub('%[key [^%]]*%]', '')):gmatch('[^%.]+') do
      parts[#parts + 1] = part:match('^%d+$') and 'N' or part
      if #parts == 4 then break end
    end
    return ('the space keeps %s alive: %s'):format(kept:gsub('^%d+ ', ''), table.concat(parts, '.'))
  end
  main = main:gsub('^[%w]+%b()[^:]*: ', '')
  -- (file:line kept: its digits as letters while the numbers go)
  main = main:gsub('%.lua:(%d+)', function(d)
    return '.lua:' .. d:gsub('%d', function(c) return string.char(65 + tonumber(c)) end)
  end)
  main = main:gsub('#%d+%b()', '#N')
  main = main:gsub('%f[%w%-]%-?%d+%.%d+e[%-+]%d+%f[^%w]', 'N'):gsub('%f[%w%-]%-?%d+%.%d+%f[^%w]', 'N')
  main = main:gsub('%f[%w%-]%-?%d+%f[^%w]', 'N')
  main = main:gsub('%.lua:(%u+)', function(d)
    return '.lua:' .. d:gsub('%u', function(c) return tostring(c:byte() - 65) end)
  end)
  return main
end

-- LuaJIT: as spec/property/space_property_spec.lua, the first programs run compiled, the
-- rest interpreted (the mix overflows the compiler's machine-code area and every flush
-- costs more than it saves).
local JIT_PROGRAMS = 60

describe('the world against its model', function()
  it('random programs of calls, callbacks, filters and errors agree with the model at every step', function()
    local jit = rawget(_G, 'jit')
    local kinds, order, failed, ran = {}, {}, 0, 0
    local ok, err = pcall(function()
      -- (STRIKE_PROGRAM past this VM's share runs too: a program is the same on every VM)
      for i = 1, math.max(PROGRAMS, ONLY or 0) do
        if jit and i == JIT_PROGRAMS + 1 then jit.off() end
        if not ONLY or ONLY == i then
          ran = ran + 1
          local pok, perr = pcall(function() WM.new(SEED, i, FEATURES, stats):run(STEPS) end)
          if not pok then
            if not WM.isFailure(perr) then error(perr, 0) end -- (a bug of the spec itself)
            failed = failed + 1
            local sig = signature(perr.msg)
            local k = kinds[sig]
            if not k then
              k = { n = 0, first = i, msg = perr.msg }
              kinds[sig] = k
              order[#order + 1] = sig
            end
            k.n = k.n + 1
          end
        end
      end
    end)
    if jit then jit.on() end
    stats.failed, stats.ran = failed, ran
    if not ok then error(err, 0) end
    if failed > 0 then
      -- (wrong answers and crashes first, then what is kept alive)
      local sorted = {}
      for j, sig in ipairs(order) do sorted[j] = sig end
      table.sort(sorted, function(x, y)
        local gx, gy = x:match('^the space keeps') ~= nil, y:match('^the space keeps') ~= nil
        if gx ~= gy then return gy end
        return kinds[x].first < kinds[y].first
      end)
      order = sorted
      local lines = { ('%d of %d programs failed (seed %d), %d kinds of failure; replay one with STRIKE_SEED=%d'
        .. ' STRIKE_PROGRAM=<n>, switch a feature off with STRIKE_FEATURES="name=false":'):format(failed, ran, SEED,
        #order, SEED) }
      for j, sig in ipairs(order) do
        local k = kinds[sig]
        lines[#lines + 1] = ('  %2d. %d programs, the first %d: %s'):format(j, k.n, k.first, sig)
      end
      lines[#lines + 1] = 'The first one in full:'
      lines[#lines + 1] = kinds[order[1]].msg
      error(table.concat(lines, '\n'), 0)
    end
  end)

  it('exercised every operation and every script action (not vacuous)', function()
    -- (counted over the programs that ran to their end: with failures, the first test fails)
    if ONLY or (stats.failed or 0) > 0 then return end
    assert((stats.steps or 0) >= 20000 * budget.SHARE, ('seed %d: only %d steps'):format(SEED, stats.steps or 0))
    assert((stats['change then query'] or 0) * 2 >= 0.3 * stats.steps,
      ('seed %d: only %d changes followed at once by a query'):format(SEED, stats['change then query'] or 0))
    local F = FEATURES
    local function on(action, ctx) return F.scripts and F[action] and F[action .. 'In' .. ctx] ~= false end
    local need = {}
    for _, q in ipairs(WM.QUERIES) do
      if not (F.queries and F.queries[q] == false) then need[#need + 1] = 'op ' .. q end
    end
    for _, c in ipairs(WM.CHANGES) do
      if (F.events or (c ~= 'on' and c ~= 'off')) and (F.responses or c ~= 'addResponse') then
        need[#need + 1] = 'op ' .. c
      end
    end
    for _, a in ipairs(WM.ACTIONS) do
      if F.scripts and F[a] and (F.events or (a ~= 'on' and a ~= 'off')) then need[#need + 1] = 'action ' .. a end
    end
    local function want(cond, ...)
      if cond then
        for _, k in ipairs({ ... }) do need[#need + 1] = k end
      end
    end
    want(true, 'colliding pairs', 'move collisions', 'moves through everything', 'snapped moves checked',
      'rayCast hits', 'rayCastAll hits', 'cast hits', 'check hits', 'queryPoint hits', 'queryRect hits',
      'queryShape hits', 'pair filter calls', 'change then query')
    want(F.events, 'events begin', 'events stay', 'events end')
    want(F.crowd, 'moves through 64 or more')
    want(F.scripts and F.raise, 'errors caught by the program')
    want(F.scripts and F.caught, 'errors caught by a script')
    want(F.events and on('collisions', 'PairFilter') and on('collisions', 'Callback'), 'collisions inside collisions')
    want(on('remove', 'PairFilter'), 'action remove in pair')
    want(on('remove', 'QueryFilter'), 'action remove in query')
    want(on('remove', 'MoveFilter'), 'action remove in move')
    want(F.events and on('remove', 'Callback'), 'action remove in event')
    want(F.events and on('off', 'Callback'), 'action off in event')
    want(on('raise', 'PairFilter'), 'action raise in pair')
    want(F.events and on('raise', 'Callback'), 'action raise in event')
    want(on('badCall', 'MoveFilter'), 'action badCall in move')
    -- an error in a callback: the next collisions() runs the rest of the events first, the
    -- callbacks after the one that raised get its event then; an error in the pair filter
    -- forgets the call's pairs
    want(F.events and on('raise', 'Callback'), 'collisions stopped in a callback', 'resumed events',
      'resumed deliveries')
    want(F.events and on('raise', 'PairFilter'), 'collisions stopped in the pair filter')
    -- a filter that moves the body being moved: docs/space.md's error; moves and casts out of
    -- the range of motion: the error naming the limit
    want(on('moveSubject', 'MoveFilter'), 'action moveSubject in move', 'subject-moved errors')
    want(on('moveSubject', 'QueryFilter'), 'action moveSubject in query')
    want(true, 'out-of-range calls')
    -- Each in at least one program in 18 of those run (20 of LuaJIT's 360, 5 of the 90 run on
    -- Lua 5.1-5.4), counted in programs, not in calls: a program draws its own world and
    -- calls, so the count is a sum over independent programs, and a few programs that do a
    -- thing many times cannot stand for the rest. The rarest (snapped moves checked, the pair
    -- filter stopping collisions()) are in 22% and 24% of the programs, the others in more (the
    -- leans of world_model.lua see to it; measured over 48 seeds on LuaJIT, 17,280 programs:
    -- at least 65 of 360 in every seed): the 70 checks together then fail for fewer than one
    -- seed in 100,000 on 90 programs, and never in practice on 360 (2e-18). The 71st, moves
    -- through 64 or more, is every crowd (every 10th program).
    local least = math.ceil(stats.ran / 18)
    local present = stats.present or {}
    local short = {}
    for _, k in ipairs(need) do
      if (present[k] or 0) < least then short[#short + 1] = ('%s in %d'):format(k, present[k] or 0) end
    end
    assert(#short == 0, ('seed %d: in fewer than %d of the %d programs: %s'):format(SEED, least, stats.ran,
      table.concat(short, ', ')))
  end)
end)
