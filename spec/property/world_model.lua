--- The model and the program generator of spec/property/world_model_property_spec.lua.
---
--- A program is a space (spec/property/space_world.lua builds its bodies: shapes, compounds,
--- nested colliders, Concave outlines, chains, at one scale) and a seeded sequence of calls
--- of its public API, each checked when it returns against a model kept here:
---
---  * the bodies in the space in add order (ranks) with their options, the pair filter, the
---    callbacks registered per event, and the pairs that have begun (the events seen so far);
---  * answers computed from the per-body API only: S.triking (pairs, check, queryShape, and
---    queryRect against a Rectangle built here), containsPoint, body:rayCast, S.weep (cast,
---    and what a move may meet on its first leg), S.ite (the contact counts), and the pair rule
---    (layers, masks, groups, then the pair filter) as docs/space.md words it ("Who collides").
---
--- Filters, pair filters, move filters, responses and event callbacks are small "scripts": a
--- pure answer computed from the body's id (so the model knows it), plus actions run on chosen
--- calls: a nested query checked against the model on the spot, add, remove, move (a transform
--- or a nested space:move) other bodies, change members, set options, on/off (of itself, of
--- later callbacks), setFilter, a bad call caught by pcall, a nested query whose own filter
--- raises (caught), moving the body that the move or cast it filters is moving, and raising an
--- error that the program's pcall around the outer call catches. Every change a script makes is
--- recorded in the frames of the calls in progress: a body removed, added, moved or given other
--- options during a call is "unsure" for that call (docs/space.md, "Your code inside a call":
--- bodies added or moved during the call "may or may not count for it"), except that a body
--- removed during a call never appears in its results. Every later call is checked against the
--- model as usual: after an error, the space must agree with the model.
---
--- The documented rules this model checks (docs/space.md, docs/moving.md), beyond the answers
--- of each query:
---  * events (docs/space.md, "Sensors and events", Events; "Your code inside a call", Errors):
---    each collisions() call's events are its ends, in pair order, then its begins and stays,
---    in pair order; a pair begins once, stays and ends only after it began, and ends once,
---    when it left the list (or a body went); a begin or stay names two bodies in the space (a
---    pair whose body was removed before its turn gets no further event in that call: it ends
---    at the next call if it began). The recorder (the first callback of every event, never
---    raising) logs the events; every game callback registered when an event starts gets it, in
---    registration order, once (one registered later gets the next events; one removed with off
---    never again). An error in a callback stops the events: the next collisions() first gives
---    the event in progress to the callbacks after the one that raised, then runs the events
---    left, then its own (checkEvents: the log of a call is the rest of the stopped call
---    followed by its own, every split tried); an error in the pair filter forgets that call's
---    pairs: no event of its own, and the next call starts from the last one that finished;
---  * collisions()' list: compacted after the events, it names no body removed during the
---    call; collisions() from inside collisions() is an error that changes nothing;
---  * a filter that moves the body being moved by move or cast (a transform of that body as a
---    whole) makes the call raise the error docs/space.md promises; a move or cast whose
---    centroid, at the start or at the goal, is beyond REACH - 1 sizes of the origin raises the
---    error naming the limit, and nothing moves and no game code runs (some are made on
---    purpose, on the edge of the range and beyond);
---  * at the end of each program, the space's own tables keep no removed body and no function
---    it no longer uses alive, but the last collision list of each move level
---    (space._cols[d][i], a move's results, which docs/moving.md says the next move reuses);
---    the library's module scratch, reached through its functions' upvalues, is not walked.
---
--- What the docs leave open, and what this model assumes there (also marked ASSUMED below):
---  * a change to the body a query asks about (check, queryShape), from its own filter: only
---    no crash; a change of a member of the body a cast or move is moving (not the body as a
---    whole): the error or an answer; the body a move is moving is never touched by its
---    responses;
---  * a body met by a move, then removed during it, may be in the move's list (docs/moving.md,
---    "Moving bodies in a space": a body the filter removes "is not met after that"): at most
---    once per time the move could meet it (a call of its filter, or else of the pair filter,
---    that returned with it still in the space);
---  * a move: the first collision is the earliest S.weep hit along the first leg among the
---    bodies it may meet (a body overlapping at the start counts at t = 0 when the move goes
---    further in; a chain in the overlap, or a move along it, may go either way), or one after
---    exact fits past the bodies met before it (docs/moving.md, Exact fits; see afterFit); it
---    ends clear of every solid body it started clear of (chains, one-sided, aside; a depth
---    within round-off aside); it never rests exactly touching a solid body it met (but where a
---    leg starts touching); with nothing solid on the line it ends at its goal, every body
---    crossed reported once; with snap and a slope (docs/moving.md, "Characters: slopes,
---    snapping, steps", defines walkable by the slope), a move that does not go up ends on
---    walkable ground within snap, when there is some; and it is never stuck meeting bodies at
---    t = 0 leg after leg without moving (the issue: a cap on a move's legs never leaves a body
---    short of where its responses take it).
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local World = require('spec.property.space_world')

local abs, max, sqrt, floor, log, cos, sin, pi = math.abs, math.max, math.sqrt, math.floor, math.log,
  math.cos, math.sin, math.pi
local huge = math.huge
local unpack = table.unpack or unpack -- luacheck: ignore 113 143
local ipairs, pairs, type, tostring, select, error, pcall, setmetatable, getmetatable = ipairs, pairs, type, tostring,
  select, error, pcall, setmetatable, getmetatable
local logRange, g = World.logRange, World.g

local K = 67108864 -- pair keys: rank of a * K + rank of b
-- (each top-level call gives the scripts a budget of actions, and an action on every k-th call
-- acts at most 5 times: a pair filter that calls collisions() on each pair would otherwise
-- make a call quadratic)
local BUDGET, EVERY = 12, 5

local WM = {}

-- STRIKE_TRACE=1: the history shows every call of a filter too.
local TRACE = os.getenv('STRIKE_TRACE') ~= nil

---------------------------------------------------------------------------------------
-- Failures and the errors scripts raise

-- A failure of the spec (raised through strike's calls when a nested check fails; the program's
-- pcalls let it through).
local Failure = {}
Failure.__tostring = function(f) return f.msg end
local function isFailure(e) return getmetatable(e) == Failure end
WM.isFailure = isFailure

-- What a script raises: error(Boom).
local Boom = {}
Boom.__tostring = function(b) return 'boom #' .. b.n end
local function isBoom(e) return getmetatable(e) == Boom end

local function pack(...) return { n = select('#', ...), ... } end

---------------------------------------------------------------------------------------
-- A program

local P = {}
P.__index = P

-- The contexts a script runs in, as the feature names spell them (FEATURES.removeInPairFilter).
local CTX = { query = 'QueryFilter', pair = 'PairFilter', move = 'MoveFilter', event = 'Callback',
  response = 'Response' }
local TAG = { query = 'Q', pair = 'P', move = 'F', event = 'C', response = 'R' }
local MAXD = 2 -- scripts run at most this deep (deeper ones answer and do nothing)

--- A new program: its world, its model and its generator. `F` is the feature table (the
--- spec's FEATURES), `stats` counts what ran (shared by every program of a run).
function WM.new(seed, index, F, stats)
  local self = setmetatable({}, P)
  local rng = PRNG.new(seed + 7919 * index)
  local w = World.new(rng, index)
  -- a moderate scale (the numeric range of moves and sweeps is another spec's business)
  w.s = logRange(rng, 0.5, 200)
  w.u = 2 ^ floor(log(w.s) / log(2)) / 8
  local function offset()
    if rng:next() < 0.4 then return 0 end
    local m = w.s * logRange(rng, 1, 1000) * (rng:next() < 0.5 and -1 or 1)
    return floor(m / w.u) * w.u
  end
  w.cx, w.cy = offset(), offset()
  setmetatable(w.info, { __mode = 'k' }) -- (the model must not keep a dropped body alive)
  self.w, self.space, self.rng, self.F, self.stats = w, w.space, rng, F, stats
  self.seed, self.index = seed, index
  -- (what the program leans toward, by the bits of its index: see LEAN_WEIGHTS)
  self.lean = { events = index % 2 == 1, pair = floor(index / 2) % 2 == 1, moves = floor(index / 4) % 2 == 1 }
  self.span = w.s + abs(w.cx) + abs(w.cy)
  self.hist, self.nhist = {}, 0
  self.stepNo = 0
  self.calls = 0                -- top-level calls made
  self.frames = {}              -- the calls in progress (see push)
  self.sdepth = 0               -- scripts running
  self.moving = {}              -- bodies a move in progress is moving -> count
  self.movePlans = {}           -- the moves in progress (their plans)
  self.probes = {}              -- bodies a query in progress asks about -> count
  self.casting = {}             -- bodies a cast in progress is moving -> count
  self.cbs = { begin = {}, stay = {}, ['end'] = {} } -- registrations, in order (the recorder first)
  self.open = {}                -- pair key -> { a, b }: begun and not ended (the events seen)
  self.evSerial = 0             -- events so far (the recorder's calls): the stream's serials
  self.rankGone = {}            -- rank of a body removed -> evSerial when it was removed
  self.pends = {}               -- the events an error left for the next collisions() (see checkEvents)
  self.carry = false            -- the event an error stopped, with the callbacks still due
  self.pf = false               -- the pair filter's script
  self.responses = {}           -- name -> script
  self.collCtx = {}             -- collisions() calls in progress
  self.outs = {}                -- out tables by depth and kind, reused across calls
  self.dropped = setmetatable({}, { __mode = 'k' }) -- removed bodies the model forgot
  self.deadFns = setmetatable({}, { __mode = 'k' }) -- functions the space must have let go
  self.rootOf = setmetatable({}, { __mode = 'kv' }) -- a member probe -> its body
  self.nscript, self.nboom, self.nreg = 0, 0, 0
  self.serials = { collisions = 0, move = 0 } -- (calls so far, any depth)
  self.seen = {}                -- the stats counted in this program
  self.budget = BUDGET
  w.fail = function(fmt, ...) self:fail(fmt, ...) end
  w.note = function(_, fmt, ...) self:log(fmt, ...) end
  return self
end

-- Count v (default 1) of k in the run's stats; stats.present[k] counts the programs in which k
-- happened at least once (the spec's coverage checks read those).
function P:count(k, v)
  local st = self.stats
  v = v or 1
  st[k] = (st[k] or 0) + v
  if v > 0 and not self.seen[k] then
    self.seen[k] = true
    local present = st.present or {}
    st.present = present
    present[k] = (present[k] or 0) + 1
  end
end

function P:D(b) return self.w:describe(b) end

-- Arguments of a message: bodies by id, kind and rank, numbers at full precision.
function P:fmt(fmt, ...)
  local args = pack(...)
  for i = 1, args.n do
    local v = args[i]
    if type(v) == 'number' then
      args[i] = g(v)
    elseif type(v) == 'table' and self.w.info[v] then
      args[i] = self:D(v)
    elseif type(v) == 'table' and type(v.x) == 'number' and type(v.y) == 'number' then
      args[i] = ('(%s, %s)'):format(g(v.x), g(v.y))
    elseif type(v) ~= 'string' then
      args[i] = tostring(v)
    end
  end
  return fmt:format(unpack(args, 1, args.n))
end

-- (STRIKE_HISTORY=n: a failure shows the last n lines instead of 30)
local HIST = tonumber(os.getenv('STRIKE_HISTORY') or '') or 40
local SHOW = os.getenv('STRIKE_HISTORY') and HIST or 30

function P:log(fmt, ...)
  local line = ('%4d %s%s'):format(self.stepNo, ('  '):rep(#self.frames), select('#', ...) > 0 and
    self:fmt(fmt, ...) or fmt)
  self.nhist = self.nhist + 1
  self.hist[(self.nhist - 1) % HIST + 1] = line
end

function P:history()
  local lines = {}
  for i = max(1, self.nhist - SHOW + 1), self.nhist do lines[#lines + 1] = '    ' .. self.hist[(i - 1) % HIST + 1] end
  return table.concat(lines, '\n')
end

function P:fail(fmt, ...)
  local w = self.w
  local msg = ('world model: seed %d program %d step %d (rerun: STRIKE_SEED=%d STRIKE_PROGRAM=%d): %s\n'
    .. '  world: scale %s, centre (%s, %s), %d bodies; the last calls (indented: from inside a call):\n%s')
    :format(self.seed, self.index, self.stepNo, self.seed, self.index, self:fmt(fmt, ...), g(w.s), g(w.cx), g(w.cy),
      #w.entries, self:history())
  error(setmetatable({ msg = msg }, Failure), 0)
end

function P:check(cond, fmt, ...)
  if not cond then self:fail(fmt, ...) end
end

---------------------------------------------------------------------------------------
-- The model's bookkeeping

function P:E(b) return self.w.entryOf[b] end
function P:id(b)
  local i = self.w.info[b]
  return i and i.id or 0
end
function P:rank(b)
  local i = self.w.info[b]
  return i and i.rank
end

-- The pair rule of docs/space.md ("Who collides"): a shared non-zero group decides alone, else
-- each layer must be in the other's mask; then the pair filter, asked with a added before b.
function P:allowed(ea, eb)
  if ea.rank > eb.rank then ea, eb = eb, ea end
  if not World.ruleAllows(ea, eb) then return false end
  return not self.pf or self:pairPass(self.pf, ea.body, eb.body)
end

function P:addBody(body, opts)
  local e = self.w:add(body, opts)
  self.w.info[body].rank = e.rank
  self:effect('added', body)
  return e
end

function P:removeBody(body)
  -- (the events of a pair whose body goes are not delivered after this: see inList)
  local e = self:E(body)
  self.rankGone[e.rank] = self.evSerial
  for _, f in ipairs(self.frames) do f.gone[body] = e end
  self.w:remove(body)
  self:effect('removed', body)
  -- half the bodies removed are forgotten by the model: the space must not keep them alive
  -- (checked at the end of the program)
  if self.F.gc and self.rng:next() < 0.5 then
    local pool = self.w.pool
    for i = #pool, 1, -1 do
      if pool[i] == body then table.remove(pool, i) end
    end
    self.dropped[body] = self:id(body)
  end
end

function P:setBody(body, opts)
  self.w:set(body, opts)
  self:effect('opts', body)
end

---------------------------------------------------------------------------------------
-- Frames: what changed during each call in progress

-- A call in progress: the bodies removed, added, moved (transformed, members changed, moved
-- by space:move) and given options during it, and whether the pair filter changed;
-- `transformed`: the bodies moved as a whole (a transform of the body itself, or a
-- space:move of it), which docs/space.md forbids for the body a move or cast is moving.
function P:push(kind)
  local f = { kind = kind, removed = {}, added = {}, moved = {}, opts = {}, transformed = {}, members = {}, pf = false,
    any = false, gone = {} } -- (gone: a body removed -> its entry then; members: a member added or removed)
  self.frames[#self.frames + 1] = f
  return f
end

function P:pop(f)
  local n = #self.frames
  if self.frames[n] ~= f then self:fail('internal: frames out of order') end
  self.frames[n] = nil
end

function P:effect(what, body)
  if what == 'moved' then self.w.info[body].exact = false end -- (no longer placed on the exact grid)
  local frames = self.frames
  for i = 1, #frames do
    local f = frames[i]
    f[what][body] = true
    f.any = true
  end
end

function P:effectPf()
  for _, f in ipairs(self.frames) do
    f.pf = true
    f.any = true
  end
end

-- Is body b unsure for the call of frame f: moved, added or given options during it
-- (docs/space.md, "Your code inside a call": "bodies added or moved during the call may or may
-- not count for it"), or removed without FEATURES.strictRemoved.
function P:unsure(f, b)
  return f.moved[b] or f.added[b] or f.opts[b] or (f.removed[b] and not self.F.strictRemoved)
end

-- Was body b removed during the call of frame f (and is not back)? Then it is in none of the
-- call's results (docs/space.md, "Your code inside a call": "A body removed during a call never
-- appears in that call's results, even when it was found before it was removed"; for
-- collisions(), the list is compacted after the events).
function P:gone(f, b)
  return f.removed[b] and not self:E(b) and self.F.strictRemoved
end

-- Did the body a query asks about (or, for a member, its body) change during the call? Then
-- anything goes for its answer (ASSUMED: the docs say nothing of it).
function P:probeChanged(f, q)
  local root = self.rootOf[q]
  return f.moved[q] or f.removed[q] or f.added[q] or f.opts[q] or root and (f.moved[root] or f.removed[root]
    or f.added[root] or f.opts[root])
end

-- Run fn(...) as a call with its own frame; errors go on up (the frame is closed first).
function P:within(kind, fn, ...)
  local f = self:push(kind)
  local r = pack(pcall(fn, ...))
  self:pop(f)
  if not r[1] then error(r[2], 0) end
  return f, unpack(r, 2, r.n)
end

-- Run fn(...) as a call with its own frame: returns the frame and pcall's results (packed).
function P:attempt(kind, fn, ...)
  local f = self:push(kind)
  local r = pack(pcall(fn, ...))
  self:pop(f)
  return f, r
end

-- A top-level call: run fn; an error raised by a script is expected (the program's pcall
-- catches it and the next calls must find the space consistent); any other error is a
-- failure.
function P:top(fn)
  self:checkKept()
  self.calls = self.calls + 1
  self.budget = BUDGET
  local ok, e = pcall(fn)
  if ok then return end
  if isFailure(e) then error(e, 0) end
  if isBoom(e) then
    self:count('errors caught by the program')
    self:log('(raised %s)', tostring(e))
    return
  end
  self:fail('the call raised an error no script raised: %s', tostring(e))
end

---------------------------------------------------------------------------------------
-- What strike gave back must stay as it was: a new table (no out) for good, collisions()'
-- records until the next collisions(), a move's list until the next move (README,
-- "Conventions", Reused tables; docs/moving.md, "The collisions list is the space's")

local KEPT_FIELDS = { 'a', 'b', 'body', 'distance', 'other', 'type', 't', 'touchX', 'touchY' }

-- Keep a snapshot of list[1..n] (a top-level call's result); `until` names the call that may
-- reuse it ('collisions', 'move') or nil.
function P:keep(what, list, n, untilKind)
  if #self.frames > 0 then return end
  local snap = { what = what, list = list, n = n, untilKind = untilKind, items = {},
    serial = untilKind and self.serials[untilKind] }
  for i = 1, n do
    local v = list[i]
    local item = { v = v }
    if type(v) == 'table' and not self.w.info[v] then
      for _, k in ipairs(KEPT_FIELDS) do item[k] = v[k] end
      if type(v.mtv) == 'table' then item.mx, item.my = v.mtv.x, v.mtv.y end
    end
    snap.items[i] = item
  end
  self.kept = snap
end

function P:checkKept()
  local snap = self.kept
  if not snap then return end
  self.kept = nil
  if snap.untilKind and self.serials[snap.untilKind] ~= snap.serial then return end
  local list = snap.list
  for i = 1, snap.n do
    local item, v = snap.items[i], list[i]
    self:check(v == item.v, '%s: result %d changed after the call (before anything could reuse it)', snap.what, i)
    if type(v) == 'table' and not self.w.info[v] then
      for _, k in ipairs(KEPT_FIELDS) do
        self:check(v[k] == item[k], '%s: result %d\'s %s changed after the call, to %s (was %s)', snap.what, i, k, v[k],
          item[k])
      end
      if type(v.mtv) == 'table' then
        self:check(v.mtv.x == item.mx and v.mtv.y == item.my, '%s: result %d\'s mtv changed after the call', snap.what,
          i)
      end
    end
  end
end

---------------------------------------------------------------------------------------
-- Scripts

local MOVE_RESPONSES = { 'slide', 'slide', 'slide', 'touch', 'cross', 'cross', 'bounce', 'none', 'stopper',
  'passer' }

-- Which actions a script of this kind may have, by weight (the feature table switches them).
local ACTION_WEIGHTS = {
  query = 3, collisions = 0.8, remove = 2, add = 1.5, transform = 2, spaceMove = 1.2, member = 0.6, set = 1,
  setFilter = 0.7, on = 0.8, off = 1.2, raise = 1, badCall = 1, caught = 0.8, moveSubject = 1.2,
}
local ACTION_ORDER = { 'query', 'collisions', 'remove', 'add', 'transform', 'spaceMove', 'member', 'set', 'setFilter',
  'on', 'off', 'raise', 'badCall', 'caught', 'moveSubject' }
WM.ACTIONS = ACTION_ORDER

-- Leans. The random mix reaches some chains in few programs: an error in a callback with
-- others after it on the same event (the next collisions() gives them the event), the pair
-- filter raising, removing a body or calling collisions(), a filter moving the body being
-- moved, a snapped move over walkable ground, a call out of the range of motion. Each program
-- leans toward some of three areas, by the bits of its index, so that each lean is in half
-- the programs of any run (and the spec's coverage checks hold for any seed):
--  * events: callbacks from the start, the first raising, with one or two after it on its
--    event; callbacks' scripts act more often, and more often remove, raise, call
--    collisions() and off (LEAN_WEIGHTS), and half of them also remove, catch an error,
--    change a member or call on (LEAN_ACTIONS);
--  * pair: a pair filter from the start that raises, removes or calls collisions(); pair
--    filters' scripts act more often, more often remove and call collisions(), and half of
--    them also raise, remove or call collisions();
--  * moves: a floor and a walker on it, walked along with snap and a slope (addWalker);
--    move options, snap and slope more often, a move with snap not going up; calls out of
--    the range of motion more often; the filters of moves and casts act more often and move
--    the body being moved more often, and half of the move filters also move it, remove,
--    catch an error or change a member; addResponse more often.
-- A lean only weighs: every operation stays possible, and a feature switched off stays off.
local LEAN_WEIGHTS = {
  event = { remove = 3, raise = 3, collisions = 2, off = 4 },
  pair = { remove = 4, collisions = 3 },
  move = { moveSubject = 3 },
  query = { moveSubject = 6 }, -- (a cast's filter, which has a subject)
}

-- What half the scripts of a kind the program leans toward do, besides their random actions
-- (one of these; the events lean has its raising callback instead: see run).
local LEAN_ACTIONS = {
  event = { 'remove', 'caught', 'member', 'on' },
  pair = { 'raise', 'remove', 'collisions' },
  move = { 'moveSubject', 'remove', 'caught', 'member' },
  query = { 'moveSubject' },
}

-- Does the program lean toward the scripts of this kind (`subject`: of a move or cast)?
function P:leaning(kind, subject)
  local lean = self.lean
  if kind == 'event' then return lean.events end
  if kind == 'pair' then return lean.pair end
  if kind == 'move' or kind == 'query' and subject then return lean.moves end
  return false
end

function P:feature(op, kind)
  local F = self.F
  if not F[op] then return false end
  if op == 'caught' and (kind == 'event' or kind == 'pair') and not F.caughtInCollisions then return false end
  local v = F[op .. 'In' .. CTX[kind]]
  return v ~= false
end

function P:pickAction(kind, s)
  local total, list = 0, {}
  for _, op in ipairs(ACTION_ORDER) do
    local wgt = ACTION_WEIGHTS[op]
    if op == 'moveSubject' and not s.subject then wgt = 0 end
    if op == 'moveSubject' and kind == 'query' and s.subject then wgt = 3 end
    if (op == 'on' or op == 'off') and not self.events then wgt = 0 end
    if op == 'off' and kind == 'event' then wgt = 3 end
    if op == 'badCall' and kind == 'move' then wgt = 3 end
    if op == 'spaceMove' and kind == 'move' then wgt = 2 end
    if op == 'raise' and kind == 'event' then wgt = 2 end
    if op == 'raise' and kind == 'pair' then wgt = 5 end
    local lw = self:leaning(kind, s.subject) and LEAN_WEIGHTS[kind][op]
    if lw and wgt > 0 then wgt = lw end
    if wgt > 0 and self:feature(op, kind) then
      total = total + wgt
      list[#list + 1] = { op, total }
    end
  end
  if total == 0 then return nil end
  local r = self.rng:next() * total
  for _, x in ipairs(list) do
    if r < x[2] then return x[1] end
  end
  return list[#list][1]
end

--- A new script of this kind: its pure answer's parameters and, unless scripts are running
--- too deep already, a few actions, each on one chosen call or on every k-th call.
--- `subject`: the body the move or cast it filters is moving (moveSubject moves it).
function P:newScript(kind, pure, subject)
  local rng = self.rng
  self.nscript = self.nscript + 1
  local s = { kind = kind, tag = TAG[kind] .. self.nscript, calls = 0, actions = {}, subject = subject }
  s.m = rng:int(2, 5)
  s.k, s.salt = rng:int(0, s.m - 1), rng:int(0, 96)
  if kind == 'move' then
    local list = {}
    for i = 1, rng:int(1, 4) do
      local r = MOVE_RESPONSES[rng:int(1, #MOVE_RESPONSES)]
      if not self.F.responses and (r == 'stopper' or r == 'passer') then r = 'slide' end
      list[i] = r
    end
    s.resps = list
  end
  local lean = not pure and self:leaning(kind, subject)
  if not pure and self.sdepth < MAXD and self.F.scripts and rng:next() < (lean and 0.85 or 0.6) then
    for _ = 1, rng:int(1, 2) do
      local op = self:pickAction(kind, s)
      if op then
        s.actions[#s.actions + 1] = { op = op, at = rng:int(1, 4), every = rng:next() < 0.3 and rng:int(2, 6) or nil }
      end
    end
  end
  if lean and LEAN_ACTIONS[kind] and rng:next() < 0.5 then self:leanAction(s, LEAN_ACTIONS[kind]) end
  return s
end

-- Add to script s one of the actions `ops` that the features allow (none when scripts run
-- too deep already), on one of its first calls or on every k-th.
function P:leanAction(s, ops)
  if not self.F.scripts or self.sdepth >= MAXD then return end
  local list = {}
  for _, op in ipairs(ops) do
    if self:feature(op, s.kind) and (op ~= 'moveSubject' or s.subject) and (op ~= 'on' and op ~= 'off' or self.events)
    then
      list[#list + 1] = op
    end
  end
  if #list == 0 then return end
  local rng = self.rng
  local op = list[rng:int(1, #list)]
  s.actions[#s.actions + 1] = { op = op, at = rng:int(1, 3), every = rng:next() < 0.4 and rng:int(2, 6) or nil }
end

function P:describeScript(s)
  if not s then return 'nil' end
  local parts = {}
  for _, a in ipairs(s.actions) do
    parts[#parts + 1] = a.op .. (a.every and ('/every ' .. a.every) or ('@' .. a.at))
  end
  return s.tag .. (#parts > 0 and ('[' .. table.concat(parts, ',') .. ']') or '')
end

-- The pure answers, from ids: deliberately not symmetric.
function P:queryPass(s, b) return (self:id(b) * 3 + s.salt) % s.m ~= s.k end
function P:pairPass(s, a, b) return (self:id(a) * 7 + self:id(b) * 3 + s.salt) % s.m ~= s.k end
function P:moveResp(s, other)
  if s.crossAll then return 'cross' end
  local r = s.resps[(self:id(other) * 5 + s.salt) % #s.resps + 1]
  if r == 'none' then return nil end
  return r
end

-- A filter's answer as some scripts spell it: any true value, or nil for false.
local TRUTHY = { true, 1, 'yes', 0 }
function P:truthy(s, v)
  if s.salt % 3 ~= 0 then return v end
  if v then return TRUTHY[s.calls % #TRUTHY + 1] end
  return s.calls % 2 == 0 and nil or false
end

-- Run the script's actions due at this call.
function P:runScript(s, ctx)
  s.calls = s.calls + 1
  -- (a callback that calls collisions() would run again inside it, without end: scripts act
  -- at most MAXD deep)
  if #s.actions == 0 or self.sdepth >= MAXD then return end
  self.sdepth = self.sdepth + 1
  local ok, e = pcall(self.runActions, self, s, ctx)
  self.sdepth = self.sdepth - 1
  if not ok then error(e, 0) end
end

local ACTIONS = {}

function P:runActions(s, ctx)
  for _, a in ipairs(s.actions) do
    if (s.calls == a.at or (a.every and s.calls % a.every == 0 and (a.fired or 0) < EVERY)) and self.budget > 0 then
      self.budget = self.budget - 1
      a.fired = (a.fired or 0) + 1
      self:count('action ' .. a.op)
      self:count('action ' .. a.op .. ' in ' .. s.kind)
      ACTIONS[a.op](self, s, ctx)
    end
  end
end

-- A query filter (body) -> boolean.
function P:queryFilterFn(s)
  return function(body)
    if TRACE then self:log('%s(%s)', s.tag, body) end
    self:check(self:E(body) ~= nil, '%s: the query filter got %s, which is not in the space', s.tag, body)
    self:runScript(s, { kind = 'query', args = { body } })
    return self:truthy(s, self:queryPass(s, body))
  end
end

-- The pair filter (a, b) -> boolean: a added before b, both in the space.
function P:pairFilterFn(s)
  return function(a, b)
    if TRACE then self:log('%s(%s, %s)', s.tag, a, b) end
    local ea, eb = self:E(a), self:E(b)
    self:check(ea and eb, '%s: the pair filter got %s, %s: not both in the space', s.tag, a, b)
    self:check(ea.rank < eb.rank, '%s: the pair filter got %s before %s', s.tag, a, b)
    self:count('pair filter calls')
    local ok, e = pcall(self.runScript, self, s, { kind = 'pair', args = { a, b } })
    if not ok then
      -- (an error out of the pair filter that collisions() itself called, not a query run
      -- from one of its callbacks)
      local ctx = self.collCtx[#self.collCtx]
      if ctx and self.frames[#self.frames] == ctx.frame then ctx.raised = ctx.raised or 'pf' end
      error(e, 0)
    end
    local pass = self:pairPass(s, a, b)
    -- (a move in progress asking about its body and another: the other may be met now, if it
    -- is still in the space; see checkMove)
    local plan = self.movePlans[#self.movePlans]
    if pass and plan and #self.frames == plan.depth and (a == plan.M or b == plan.M) then
      local o = a == plan.M and b or a
      if self:E(o) then plan.pfc[o] = (plan.pfc[o] or 0) + 1 end
    end
    return self:truthy(s, pass)
  end
end

-- A move's filter (body, other) -> response name or nil. plan.fc counts, per other, the calls
-- that returned with other still in the space (a body is met at most once per call: see
-- checkMove).
function P:moveFilterFn(s, plan)
  return function(body, other)
    if TRACE then self:log('%s(%s, %s)', s.tag, body, other) end
    self:check(body == plan.M, '%s: the move filter of %s got %s as the body moved', s.tag, plan.M, body)
    self:check(self:E(other) ~= nil and other ~= body, '%s: the move filter got %s, which is not in the space', s.tag,
      other)
    self:runScript(s, { kind = 'move', args = { other }, M = body })
    if self:E(other) then plan.fc[other] = (plan.fc[other] or 0) + 1 end
    return self:moveResp(s, other)
  end
end

function P:setPairFilter(s)
  local old = self.pf
  if old then self.deadFns[old.fn] = 'the pair filter ' .. old.tag end
  if s then
    s.fn = self:pairFilterFn(s)
    self.deadFns[s.fn] = nil
  end
  self.pf = s or false
  self.space:setFilter(s and s.fn or nil)
  self:effectPf()
  self:log('setFilter(%s)', s and self:describeScript(s) or 'nil')
end

---------------------------------------------------------------------------------------
-- Events: the recorder and the callbacks

-- The event being delivered in the collisions() call ctx: { ev = the recorder's entry, rest =
-- the game's callbacks registered for its kind when it started, in order, pos = the next one
-- due }. docs/space.md ("Sensors and events", Events): callbacks run in the order they were
-- registered; one registered while the events run gets them from the next event on; one removed
-- with off is never called after off returns. ("Your code inside a call", Errors): an error in
-- a callback stops the events there, and the next collisions() runs the rest first -- the
-- callbacks of that event not yet called, then the events left -- so each callback sees every
-- event once.
function P:finishEvent(ctx)
  local cur = ctx.cur
  if not cur then return end
  ctx.cur = nil
  local ev = cur.ev
  for j = cur.pos, #cur.rest do
    local reg = cur.rest[j]
    if not reg.off then
      self:fail('collisions(): callback %s never got %s %s-%s (event %d of the stream), although it was registered'
        .. ' when the event started and never removed', reg.tag, ev.event, ev.a, ev.b, ev.serial)
    end
  end
end

-- The recorder is the first callback of every event and never goes: it logs each event of a
-- collisions() call, and starts its deliveries to the game's callbacks.
function P:recorderFn(E)
  return function(a, b, rec)
    local ctx = self.collCtx[#self.collCtx]
    self:check(ctx ~= nil, 'a %s event for %s-%s outside collisions()', E, a, b)
    self:finishEvent(ctx)
    self.evSerial = self.evSerial + 1
    local ev = { event = E, a = a, b = b, serial = self.evSerial, ra = type(rec) == 'table' and rec.a,
      rb = type(rec) == 'table' and rec.b, sensor = type(rec) == 'table' and rec.sensor }
    local m = type(rec) == 'table' and rec.mtv
    if type(m) == 'table' then ev.mtv = { x = m.x, y = m.y } else ev.mtv = m end
    local c = type(rec) == 'table' and rec.contacts
    ev.ctype, ev.ncontacts = type(c), type(c) == 'table' and c.count or nil
    ctx.log[#ctx.log + 1] = ev
    local i = #ctx.log
    self:check(ev.ra == a and ev.rb == b, 'collisions(): event %d, %s %s-%s: the record holds %s-%s', i, E, a, b, ev.ra,
      ev.rb)
    if E ~= 'end' then
      -- (docs/space.md, "Your code inside a call", Errors: a pair whose body was removed
      -- during the events gets no further event in that call; "Sensors and events": a body
      -- removed and added again is a new body)
      local ea, eb = self:E(a), self:E(b)
      self:check(ea and eb, 'collisions(): event %d, %s %s-%s: a body removed from the space before the event', i,
        E, a, b)
      self:check(ea.rank < eb.rank, 'collisions(): event %d, %s %s-%s: b added before a', i, E, a, b)
      ev.key = ea.rank * K + eb.rank
    end
    local list, rest = self.cbs[E], {}
    for j = 1, #list do
      if list[j].script then rest[#rest + 1] = list[j] end
    end
    ctx.cur = { ev = ev, rest = rest, pos = 1 }
  end
end

-- A game callback: each call must be the next one due for the event being delivered.
function P:newCallback(E, s)
  self.nreg = self.nreg + 1
  local reg = { event = E, script = s, tag = s.tag .. ':' .. E }
  reg.fn = function(a, b)
    local ctx = self.collCtx[#self.collCtx]
    self:check(ctx ~= nil, 'callback %s called with %s-%s outside collisions()', reg.tag, a, b)
    self:check(not reg.off, 'callback %s got %s %s-%s after it was removed with off()', reg.tag, E, a, b)
    local cur = ctx.cur
    self:check(cur ~= nil, 'callback %s got %s-%s; no event is being delivered', reg.tag, a, b)
    local ev = cur.ev
    self:check(ev.event == E and ev.a == a and ev.b == b, 'callback %s got %s-%s; the event in progress is %s %s-%s',
      reg.tag, a, b, ev.event, ev.a, ev.b)
    local rest, j = cur.rest, cur.pos
    while rest[j] and rest[j].off do j = j + 1 end
    self:check(rest[j] == reg, 'callback %s got %s %s-%s (event %d of the stream); the next one due is %s', reg.tag,
      E, a, b, ev.serial, rest[j] and rest[j].tag or 'none (registered after the event started, or called twice)')
    cur.pos = j + 1
    if cur.carried then self:count('resumed deliveries') end
    local ok, e = pcall(self.runScript, self, s, { kind = 'event', args = { a, b }, reg = reg })
    if not ok then
      ctx.raised = ctx.raised or 'callback'
      error(e, 0)
    end
  end
  return reg
end

function P:on(E, s)
  local reg = self:newCallback(E, s)
  local list = self.cbs[E]
  list[#list + 1] = reg
  local got = self.space:on(E, reg.fn)
  self:check(got == reg.fn, 'space:on did not return the callback')
  self:log('on(%s, %s)', E, self:describeScript(s))
  return reg
end

function P:off(reg)
  local list = self.cbs[reg.event]
  for i = 1, #list do
    if list[i] == reg then
      table.remove(list, i)
      break
    end
  end
  reg.off = true
  self.deadFns[reg.fn] = 'the callback ' .. reg.tag
  local found = self.space:off(reg.event, reg.fn)
  self:check(found == true, 'space:off(%s, %s) returned %s for a registered callback', reg.event, reg.tag, found)
  self:log('off(%s)', reg.tag)
end

---------------------------------------------------------------------------------------
-- Targets of the scripts' actions

-- A body a script may act on: in the space, not being moved by a move in progress, and
-- (unless FEATURES.touchProbe) not the subject of a query in progress; the script's own
-- arguments are picked half the time.
function P:pickTarget(ctx)
  local rng = self.rng
  local function ok(b)
    return self:E(b) and not self.moving[b] and (self.F.touchProbe or not self.probes[b])
  end
  if ctx and ctx.args and rng:next() < 0.5 then
    local b = ctx.args[rng:int(1, #ctx.args)]
    if ok(b) then return b end
  end
  local E = self.w.entries
  if #E == 0 then return nil end
  for _ = 1, 4 do
    local b = E[rng:int(1, #E)].body
    if ok(b) then return b end
  end
  return nil
end

---------------------------------------------------------------------------------------
-- Changes that can be replayed on a copy (a move's start state is computed on the copy of
-- a body changed just before, so that nothing reads the changed body before the move)

-- A member of collider c (not c), by path of indices, or nil.
function P:memberPath(c)
  local rng, node, path = self.rng, c, {}
  repeat
    local kids = { node:unpack() }
    if #kids == 0 then return nil end
    local i = rng:int(1, #kids)
    path[#path + 1] = i
    node = kids[i]
  until node.shapes == nil or rng:next() < 0.5
  return path, node
end

local function follow(root, path)
  local node = root
  for _, i in ipairs(path or {}) do node = select(i, node:unpack()) end
  return node
end

--- A random transform of obj (a body or a member): apply(o) does it to o or to its copy,
--- with a description and the point where obj ends up (roughly: a target for a query).
function P:transformOp(obj)
  local rng, s = self.rng, self.w.s
  local cx, cy = obj:getCentroid()
  local r = rng:next()
  if r < 0.03 then
    local d, a = self.w:side() * logRange(rng, 10, 1e3), rng:range(-pi, pi)
    local dx, dy = d * cos(a), d * sin(a)
    return function(o) o:translate(dx, dy) end, ('translate far (%s, %s)'):format(g(dx), g(dy)), cx + dx, cy + dy
  elseif r < 0.45 then
    local d, a = s * logRange(rng, 0.01, 4), rng:range(-pi, pi)
    local dx, dy = d * cos(a), d * sin(a)
    return function(o) o:translate(dx, dy) end, ('translate (%s, %s)'):format(g(dx), g(dy)), cx + dx, cy + dy
  elseif r < 0.58 then
    local x, y = self.w:randomPoint()
    return function(o) o:translateTo(x, y) end, ('translateTo (%s, %s)'):format(g(x), g(y)), x, y
  elseif r < 0.72 then
    local a = rng:range(-pi, pi)
    return function(o) o:rotate(a) end, 'rotate ' .. g(a), cx, cy
  elseif r < 0.8 then
    local a = rng:range(-0.5, 0.5)
    local px, py = cx + s * rng:range(-2, 2), cy + s * rng:range(-2, 2)
    local ca, sa = cos(a), sin(a)
    local tx, ty = px + ca * (cx - px) - sa * (cy - py), py + sa * (cx - px) + ca * (cy - py)
    return function(o) o:rotate(a, px, py) end, ('rotate %s about (%s, %s)'):format(g(a), g(px), g(py)), tx, ty
  elseif r < 0.86 then
    local a = rng:range(-pi, pi)
    return function(o) o:rotateTo(a) end, 'rotateTo ' .. g(a), cx, cy
  end
  local R = obj:getRadius()
  local sf = rng:range(0.7, 1.4)
  if R > 0 and (R * sf > 10 * s or R * sf < 0.05 * s) then sf = 1 / sf end
  return function(o) o:scale(sf) end, 'scale ' .. g(sf), cx, cy
end

-- Kinds of bodies whose members the program changes (not Concave or Chain: their pieces
-- are theirs).
local MUTABLE = { single = true, compound = true }

--- A random geometric change of body X (in the space): a transform of X or of a member,
--- a member added or removed. Returns { apply = fn(root), desc, tx, ty } or nil.
function P:geometryChange(X)
  local rng = self.rng
  local kind = self.w.info[X].kind
  local r = rng:next()
  if MUTABLE[kind] and r < 0.2 then
    local path, node = self:memberPath(X)
    if path then
      local apply, desc, tx, ty = self:transformOp(node)
      return { apply = function(root) apply(follow(root, path)) end, desc = desc .. ' a member (depth ' .. #path ..
        ') of', tx = tx, ty = ty, what = 'member' }
    end
  elseif MUTABLE[kind] and r < 0.27 then
    local cx, cy = X:getCentroid()
    if X:getShapeCount() == 0 then cx, cy = self.w:randomPoint() end
    local s = self.w.s
    local shape = self.w:shape(cx + s * rng:range(-1, 1), cy + s * rng:range(-1, 1), s * logRange(rng, 0.2, 1))
    local spare = shape:copy()
    local used = false
    self.w.info[X].kind = 'compound'
    return { apply = function(root)
      if not used then
        used = true
        root:add(shape)
      else
        root:add(spare)
      end
    end, desc = 'Collider:add to', tx = cx, ty = cy, what = 'memberAdd' }
  elseif MUTABLE[kind] and r < 0.34 then
    local count = select('#', X:unpack())
    -- (of the body a cast is moving: see FEATURES.memberRemovedFromCast)
    if count > 1 and (self.F.memberRemovedFromCast or not self.casting[X]) then
      local i = rng:int(1, count)
      local cx, cy = X:getCentroid()
      local first = true
      return { apply = function(root)
        local child = root:remove(i)
        if first then -- (the real one: a free body now)
          first = false
          self.w:register(child, child.shapes and 'compound' or 'shape')
          self.w.pool[#self.w.pool + 1] = child
        end
      end, desc = 'Collider:remove(' .. i .. ') from', tx = cx, ty = cy, what = 'memberRemove' }
    end
  end
  local apply, desc, tx, ty = self:transformOp(X)
  return { apply = apply, desc = desc, tx = tx, ty = ty, what = 'transform' }
end

-- Place exact body b against exact body a (their bounds share a side) by a dyadic
-- translation: returns the translation (as space_world's touch).
function P:touchDelta(a, b)
  local rng, u = self.rng, self.w.u
  local ax0, ay0, ax1, ay1 = a:getBounds()
  local bx0, by0, bx1, by1 = b:getBounds()
  local function along(lo0, hi0, lo1, hi1)
    local w1 = hi1 - lo1
    local k0, k1 = math.ceil((lo0 - w1) / u) + 1, floor(hi0 / u) - 1
    if k1 < k0 then k1 = k0 end
    return rng:int(k0, k1) * u - lo1
  end
  local side = rng:int(1, 4)
  if side == 1 then return ax1 - bx0, along(ay0, ay1, by0, by1) end
  if side == 2 then return ax0 - bx1, along(ay0, ay1, by0, by1) end
  if side == 3 then return along(ax0, ax1, bx0, bx1), ay1 - by0 end
  return along(ax0, ax1, bx0, bx1), ay0 - by1
end

---------------------------------------------------------------------------------------
-- out tables: kept per depth and kind and reused across calls, sometimes with junk

local LIST_KINDS = { 'collisions', 'check', 'queryPoint', 'queryRect', 'queryShape', 'rayCastAll', 'bodies' }

function P:junk(out)
  local rng, F = self.rng, self.F
  local r = rng:next()
  local n = #out
  local m = rng:int(1, 10)
  local E = self.w.entries
  local function someBody()
    local pool = self.w.pool
    if #pool > 0 and rng:next() < 0.3 then return pool[rng:int(1, #pool)] end
    if #E > 0 then return E[rng:int(1, #E)].body end
    return 42
  end
  if r < 0.2 then -- stale numbers after the previous result
    for i = n + 1, n + m do out[i] = rng:range(-1e3, 1e3) end
    return 'stale numbers'
  elseif r < 0.35 then -- numbers over it
    for i = 1, m do out[i] = rng:int(-5, 200) end
    return 'numbers'
  elseif r < 0.5 then -- bodies, some out of the space
    for i = 1, m do out[i] = someBody() end
    return 'bodies'
  elseif r < 0.65 then -- records of other kinds, and other values
    for i = 1, m do
      local k = rng:int(1, 6)
      if k == 1 then out[i] = { a = someBody(), b = someBody(), mtv = false }
      elseif k == 2 then out[i] = { body = someBody(), distance = 1, x = 0, y = 0 }
      elseif k == 3 then out[i] = 'junk'
      elseif k == 4 then out[i] = true
      elseif k == 5 then out[i] = { x = 1, y = 2 }
      else out[i] = someBody() end
    end
    return 'records'
  elseif r < 0.75 then
    out.n, out.count, out.x, out.name = rng:int(0, 9), 'many', {}, 'out'
    return 'fields'
  elseif r < 0.85 and F.holeyJunk then
    out[n + 2] = rng:int(1, 9)
    return 'a hole, then a number'
  end
  return nil -- (its own previous result, as it is)
end

-- The out table for a call of this kind: nil, a new one, or the one kept (sometimes with junk,
-- sometimes another kind's).
function P:outFor(kind)
  local rng = self.rng
  local r = rng:next()
  if r < 0.1 then return nil, 'no out' end
  if r < 0.16 then return {}, 'a new out' end
  local d = self.sdepth
  local outs = self.outs[d]
  if not outs then
    outs = {}
    self.outs[d] = outs
  end
  local take = kind
  if kind ~= 'cast' and self.F.swapOuts and rng:next() < 0.06 then take = LIST_KINDS[rng:int(1, #LIST_KINDS)] end
  local out = outs[take]
  if not out then
    out = {}
    outs[take] = out
  end
  local how = take == kind and 'its out' or ('the out of ' .. take)
  if self.F.junk and rng:next() < 0.3 then
    if kind == 'cast' then
      out.t, out.body, out.overlapping, out.nx = rng:range(0, 1), self.w.entries[1] and self.w.entries[1].body, 'x', 7
      how = how .. ' + stale fields'
    else
      local j = self:junk(out)
      if j then how = how .. ' + ' .. j end
    end
  end
  return out, how
end

-- The end of a list result: the table returned is `out` when given, and nothing follows the n
-- results (ipairs stops there).
function P:listEnd(what, got, n, out)
  self:check(type(got) == 'table', '%s returned %s, not a list', what, got)
  self:check(type(n) == 'number' and n >= 0 and n % 1 == 0, '%s returned the count %s', what, n)
  if out then self:check(got == out, '%s returned another table than its out', what) end
  self:check(got[n + 1] == nil, '%s: %d results, and %s after them', what, n, got[n + 1])
  for i = 1, n do self:check(got[i] ~= nil, '%s: result %d of %d is nil', what, i, n) end
end

---------------------------------------------------------------------------------------
-- Query filters

-- A random query filter for a query: nil, {mask = ...}, or a script; with the model's pass(e).
-- (`subject`: the body a cast moves)
function P:queryFilter(pure, subject)
  local rng = self.rng
  local r = rng:next()
  if r < 0.35 then return { pass = function() return true end, desc = 'no filter' } end
  if r < 0.55 then
    local list, set = {}, {}
    for _, name in ipairs(self.w.layers) do
      if rng:next() < 0.5 then
        list[#list + 1] = name
        set[name] = true
      end
    end
    return { filter = { mask = list }, pass = function(e) return set[e.layer] == true end, desc = 'mask {' ..
      table.concat(list, ',') .. '}' }
  end
  local s = self:newScript('query', pure, subject)
  local fn = self:queryFilterFn(s)
  return { filter = fn, script = s, pass = function(e) return self:queryPass(s, e.body) end,
    desc = self:describeScript(s) }
end

-- After a query: a filter that is no longer anybody's must not be kept by the space.
-- fn(...) with `body` counted as the subject of a query in progress (self.probes) while it
-- runs; returns what fn returns (fn must not raise: a pcall or P:attempt).
function P:probing(body, fn, ...)
  local probes = self.probes
  probes[body] = (probes[body] or 0) + 1
  local r = pack(fn(...))
  probes[body] = probes[body] > 1 and probes[body] - 1 or nil
  return unpack(r, 1, r.n)
end

function P:release(qf)
  if qf and type(qf.filter) == 'function' then self.deadFns[qf.filter] = 'the query filter ' .. qf.desc end
end

---------------------------------------------------------------------------------------
-- Lists of bodies against the model

--- got[1..n] (bodies; `field` names the body in a record) against exp (the model's bodies, in
--- rank order): rank order, nothing removed during the call, every sure body as the model
--- says; unsure ones (changed during the call) either way.
function P:compareBodies(what, f, got, n, exp, field, isUnsure)
  local want = {}
  for _, b in ipairs(exp) do want[b] = true end
  local seen, last = {}, -huge
  for i = 1, n do
    local r = got[i]
    local b = field and type(r) == 'table' and r[field] or (not field and r) or nil
    self:check(type(b) == 'table' and self.w.info[b], '%s: result %d is %s, not a body', what, i, b)
    self:check(not self:gone(f, b), '%s: %s was removed during the call, and it is result %d', what, b, i)
    self:check(self:E(b) or f.removed[b], '%s: result %d, %s, is not in the space', what, i, b)
    local rk = self:rank(b)
    self:check(rk > last, '%s: result %d, %s, is not in rank order (or twice)', what, i, b)
    last = rk
    seen[b] = true
    if not (isUnsure and isUnsure(b)) then
      self:check(want[b], '%s: result %d is %s; the model leaves it out (%d results, the model %d)', what, i, b, n,
        #exp)
    end
  end
  for _, b in ipairs(exp) do
    if not seen[b] and not (isUnsure and isUnsure(b)) then
      self:fail('%s: %s is missing (%d results, the model %d)', what, b, n, #exp)
    end
  end
end

local function mtvMatches(m, e)
  if type(m) ~= 'table' or type(m.x) ~= 'number' or type(m.y) ~= 'number' then return false end
  local L = sqrt(e.x * e.x + e.y * e.y)
  return abs(m.x - e.x) <= 1e-9 * L and abs(m.y - e.y) <= 1e-9 * L
end

---------------------------------------------------------------------------------------
-- Queries: each plans its arguments (around a target point when given), calls, and checks

local Q = {}
WM.QUERIES = { 'collisions', 'check', 'queryPoint', 'queryRect', 'queryShape', 'rayCast', 'rayCastAll', 'cast',
  'move', 'bodies' }

-- A point to aim at: the target, or a body's centroid, or a point of the region.
function P:aim(target)
  if target then return target[1], target[2] end
  local E = self.w.entries
  if #E > 0 and self.rng:next() < 0.6 then
    local b = E[self.rng:int(1, #E)].body
    if not b.shapes or b:getShapeCount() > 0 then return b:getCentroid() end
  end
  return self.w:randomPoint()
end

-- A member of a body in the space (a leaf or a nested collider), or nil.
function P:randomMember()
  local list = {}
  for _, e in ipairs(self.w.entries) do
    if e.body.shapes and e.body:getShapeCount() > 0 then list[#list + 1] = e.body end
  end
  if #list == 0 then return nil end
  local root = list[self.rng:int(1, #list)]
  local _, node = self:memberPath(root)
  if node and not self.w.info[node] then self.w:register(node, 'member of #' .. self:id(root)) end
  if node then self.rootOf[node] = root end
  return node
end

-- A transient probe (a shape or a body out of the space) about (x, y).
function P:transient(x, y)
  local w = self.w
  if self.rng:next() < 0.7 then
    return w:register(w:shape(x, y, w.s * logRange(self.rng, 0.2, 3)), 'transient')
  end
  return w:newBody(x, y)
end

------------------------------------------------------------------ queryPoint

function Q.queryPoint(self, target)
  local x, y = self:aim(target)
  local E = self.w.entries
  if not target and #E > 0 and self.rng:next() < 0.2 then -- a vertex: on a boundary
    local leaf = World.firstLeaf(E[self.rng:int(1, #E)].body)
    local k = leaf and leaf:getVertexCount() or 0
    if k > 0 then x, y = leaf:getVertex(self.rng:int(1, k)) end
  end
  local qf = self:queryFilter()
  local out, how = self:outFor('queryPoint')
  local what = self:fmt('queryPoint(%s, %s, %s, %s)', x, y, qf.desc, how)
  self:log(what)
  local f, got, n = self:within('queryPoint', self.space.queryPoint, self.space, x, y, qf.filter, out)
  self:release(qf)
  self:listEnd(what, got, n, out)
  local exp = {}
  for _, e in ipairs(self.w.entries) do
    if qf.pass(e) and e.body:containsPoint(x, y) then exp[#exp + 1] = e.body end
  end
  self:compareBodies(what, f, got, n, exp, nil, function(b) return self:unsure(f, b) end)
  self:count('queryPoint hits', n)
  if not out then self:keep(what, got, n) end
end

------------------------------------------------------------------ queryRect

function Q.queryRect(self, target)
  local rng, w = self.rng, self.w
  local x, y = self:aim(target)
  local wd, ht = w.s * logRange(rng, 0.05, 6), w.s * logRange(rng, 0.05, 6)
  x, y = x - wd * rng:next(), y - ht * rng:next()
  if rng:next() < 0.3 then x, y, wd, ht = w:snap(x), w:snap(y), w.u * rng:int(1, 64), w.u * rng:int(1, 64) end
  -- (as spec/property/space_property_spec.lua: the space places the corners at the centre
  -- -+ half the sides; when a Rectangle made at the origin and moved there has other
  -- corners, bodies within a rounding of its sides may go either way)
  local hw, hh = wd / 2, ht / 2
  local cx, cy = x + hw, y + hh
  local R = S.hapes.Rectangle(0, 0, wd, ht):translate(cx, cy)
  local x0, y0, x1, y1 = R:getBounds()
  local exact = x0 == cx - hw and x1 == cx + hw and y0 == cy - hh and y1 == cy + hh
  local inner, outer = R, R
  if not exact then
    local pad = 1e-12 * (abs(cx) + abs(cy) + wd + ht)
    inner = S.hapes.Rectangle(0, 0, max(wd - 2 * pad, hw), max(ht - 2 * pad, hh)):translate(cx, cy)
    outer = S.hapes.Rectangle(0, 0, wd + 2 * pad, ht + 2 * pad):translate(cx, cy)
  end
  local qf = self:queryFilter()
  local out, how = self:outFor('queryRect')
  local what = self:fmt('queryRect(%s, %s, %s, %s, %s, %s)', x, y, wd, ht, qf.desc, how)
  self:log(what)
  local f, got, n = self:within('queryRect', self.space.queryRect, self.space, x, y, wd, ht, qf.filter, out)
  self:release(qf)
  self:listEnd(what, got, n, out)
  local exp, either = {}, {}
  for _, e in ipairs(self.w.entries) do
    if qf.pass(e) then
      if S.triking(inner, e.body) then
        exp[#exp + 1] = e.body
      elseif not exact and S.triking(outer, e.body) then
        either[e.body] = true
      end
    end
  end
  self:compareBodies(what, f, got, n, exp, nil, function(b) return self:unsure(f, b) or either[b] end)
  self:count('queryRect hits', n)
  if not out then self:keep(what, got, n) end
end

------------------------------------------------------------------ queryShape

function Q.queryShape(self, target, X)
  local rng = self.rng
  local q, how
  local E = self.w.entries
  if X and self:E(X) and rng:next() < 0.5 then
    q, how = X, 'the body changed'
  elseif #E > 0 and rng:next() < 0.25 then
    q, how = E[rng:int(1, #E)].body, 'a body in the space'
  elseif #self.w.pool > 0 and rng:next() < 0.15 then
    q, how = self.w.pool[rng:int(1, #self.w.pool)], 'a body out of the space'
  elseif rng:next() < 0.1 then
    q, how = self:randomMember(), 'a member of a body in the space'
  end
  if not q then
    local x, y = self:aim(target)
    q, how = self:transient(x, y), 'a transient'
  end
  local qf = self:queryFilter()
  local out, ohow = self:outFor('queryShape')
  local what = self:fmt('queryShape(%s %s, %s, %s)', how, q, qf.desc, ohow)
  self:log(what)
  local ok, f, got, n = self:probing(q, pcall, self.within, self, 'queryShape', self.space.queryShape, self.space, q,
    qf.filter, out)
  self:release(qf)
  if not ok then error(f, 0) end
  self:listEnd(what, got, n, out)
  if self:probeChanged(f, q) then return end
  local exp = {}
  for _, e in ipairs(self.w.entries) do
    if e.body ~= q and qf.pass(e) and S.triking(q, e.body) then exp[#exp + 1] = e.body end
  end
  self:compareBodies(what, f, got, n, exp, nil, function(b) return self:unsure(f, b) end)
  self:count('queryShape hits', n)
  if not out then self:keep(what, got, n) end
end

------------------------------------------------------------------ check

function Q.check(self, target, X)
  local rng = self.rng
  local E = self.w.entries
  local body, how
  if X and self:E(X) and rng:next() < 0.6 then
    body, how = X, 'the body changed'
  elseif #E > 0 and rng:next() < 0.7 then
    body, how = E[rng:int(1, #E)].body, 'in the space'
  elseif rng:next() < 0.3 then
    body, how = self:randomMember(), 'a member of a body in the space'
  end
  if not body then
    local x, y = self:aim(target)
    body, how = self:transient(x, y), 'transient'
  end
  local qf = self:queryFilter()
  local out, ohow = self:outFor('check')
  local what = self:fmt('check(%s %s, %s, %s)', how, body, qf.desc, ohow)
  self:log(what)
  local ok, f, got, n = self:probing(body, pcall, self.within, self, 'check', self.space.check, self.space, body,
    qf.filter, out)
  self:release(qf)
  if not ok then error(f, 0) end
  self:listEnd(what, got, n, out)
  for i = 1, n do
    local r = got[i]
    self:check(type(r) == 'table' and r.a == body, '%s: record %d is not {a = the body, ...}: %s', what, i, r)
  end
  if self:probeChanged(f, body) then return end
  local inside = self:E(body)
  local exp, mtvs = {}, {}
  if not (inside and inside.sensor) then
    for _, e in ipairs(self.w.entries) do
      if e.body ~= body and not e.sensor and qf.pass(e) and (not inside or self:allowed(inside, e)) then
        local m = S.triking(body, e.body)
        if m then
          exp[#exp + 1] = e.body
          mtvs[e.body] = m
        end
      end
    end
  end
  local pfUnsure = f.pf and inside
  self:compareBodies(what, f, got, n, exp, 'b', function(b) return pfUnsure or self:unsure(f, b) end)
  for i = 1, n do
    local r = got[i]
    local m = mtvs[r.b]
    if m and not self:unsure(f, r.b) then
      self:check(mtvMatches(r.mtv, m), '%s: record %d (%s): mtv %s, S.triking %s', what, i, r.b, r.mtv, m)
    end
  end
  self:count('check hits', n)
  if not out then self:keep(what, got, n) end
end

------------------------------------------------------------------ rays

function P:randomRay(target)
  local rng, w = self.rng, self.w
  local x, y = w:randomPoint()
  if rng:next() < 0.1 then
    local L, a = w:side() * logRange(rng, 2, 100), rng:range(-pi, pi)
    x, y = w.cx + L * cos(a), w.cy + L * sin(a)
  end
  local dx, dy
  local tx, ty = self:aim(target)
  if target or rng:next() < 0.6 then
    dx, dy = tx - x, ty - y
  end
  if not dx or (dx == 0 and dy == 0) then
    local a = rng:range(-pi, pi)
    dx, dy = cos(a), sin(a)
  end
  if rng:next() < 0.15 then -- along an axis, through the target (exact sides and corners)
    local k = rng:int(1, 4)
    dx, dy = ({ 1, -1, 0, 0 })[k], ({ 0, 0, 1, -1 })[k]
    if k <= 2 then y = w:snap(ty) else x = w:snap(tx) end
  end
  local k = logRange(rng, 0.01, 100)
  dx, dy = dx * k, dy * k
  local maxd
  local r = rng:next()
  if r < 0.4 then maxd = rng:range(0, 2) * (w:side() + sqrt((x - w.cx) ^ 2 + (y - w.cy) ^ 2)) end
  if r > 0.98 then maxd = 0 end
  return x, y, dx, dy, maxd
end

-- Every hit of the ray on the bodies the filter passes, sorted by distance then rank.
function P:rayHits(x, y, dx, dy, maxd, pass)
  local hits = {}
  for _, e in ipairs(self.w.entries) do
    if pass(e) then
      local t, hx, hy, nx, ny, shape = e.body:rayCast(x, y, dx, dy, maxd)
      if t then
        hits[#hits + 1] = { body = e.body, rank = e.rank, t = t, x = hx, y = hy, nx = nx, ny = ny,
          shape = shape or e.body }
      end
    end
  end
  table.sort(hits, function(p, q)
    if p.t ~= q.t then return p.t < q.t end
    return p.rank < q.rank
  end)
  return hits
end

function P:sameHit(what, h, body, t, hx, hy, nx, ny, shape)
  self:check(abs(t - h.t) <= 1e-9 * h.t, '%s (%s): distance %s, body:rayCast %s', what, body, t, h.t)
  local ptol = 1e-9 * (self.span + h.t)
  self:check(abs(hx - h.x) <= ptol and abs(hy - h.y) <= ptol, '%s (%s): point (%s, %s), body:rayCast (%s, %s)', what,
    body, hx, hy, h.x, h.y)
  self:check(abs(nx - h.nx) <= 1e-9 and abs(ny - h.ny) <= 1e-9, '%s (%s): normal (%s, %s), body:rayCast (%s, %s)',
    what, body, nx, ny, h.nx, h.ny)
  self:check(shape == h.shape, '%s (%s): shape %s, body:rayCast %s', what, body, shape, h.shape)
end

function Q.rayCast(self, target)
  local x, y, dx, dy, maxd = self:randomRay(target)
  local qf = self:queryFilter()
  local what = self:fmt('rayCast(%s, %s, %s, %s, %s, %s)', x, y, dx, dy, maxd, qf.desc)
  self:log(what)
  local f, body, t, hx, hy, nx, ny, shape = self:within('rayCast', self.space.rayCast, self.space, x, y, dx, dy, maxd,
    qf.filter)
  self:release(qf)
  local hits = self:rayHits(x, y, dx, dy, maxd, qf.pass)
  -- the closest sure hit (unsure bodies may or may not count)
  local best
  for _, h in ipairs(hits) do
    if not self:unsure(f, h.body) then
      best = h
      break
    end
  end
  if body == nil then
    self:check(best == nil, '%s: no hit; the model hits %s at %s', what, best and best.body, best and best.t)
    return
  end
  self:check(self.w.info[body] ~= nil, '%s: hit %s, not a body', what, body)
  self:check(not self:gone(f, body), '%s: hit %s, which was removed during the call', what, body)
  if self:unsure(f, body) then
    self:check(not best or t <= best.t * (1 + 1e-9), '%s: hit %s (changed during the call) at %s, beyond %s at %s',
      what, body, t, best and best.body, best and best.t)
    return
  end
  self:check(best ~= nil, '%s: hit %s at %s; the model hits nothing', what, body, t)
  local mine
  for _, h in ipairs(hits) do
    if h.body == body then mine = h end
  end
  self:check(mine ~= nil, '%s: hit %s at %s, which body:rayCast misses (the model: %s at %s)', what, body, t, best.body,
    best.t)
  -- (ties by rank; a tie within a rounding either way)
  if body ~= best.body then
    self:check(mine.t <= best.t * (1 + 1e-12) + 1e-300 and mine.t ~= best.t, '%s: hit %s at %s; the model %s at %s',
      what, body, mine.t, best.body, best.t)
  end
  self:sameHit(what, mine, body, t, hx, hy, nx, ny, shape)
  self:count('rayCast hits')
end

function Q.rayCastAll(self, target)
  local x, y, dx, dy, maxd = self:randomRay(target)
  local qf = self:queryFilter()
  local out, how = self:outFor('rayCastAll')
  local what = self:fmt('rayCastAll(%s, %s, %s, %s, %s, %s, %s)', x, y, dx, dy, maxd, qf.desc, how)
  self:log(what)
  local f, got, n = self:within('rayCastAll', self.space.rayCastAll, self.space, x, y, dx, dy, maxd, qf.filter, out)
  self:release(qf)
  self:listEnd(what, got, n, out)
  local hits = self:rayHits(x, y, dx, dy, maxd, qf.pass)
  local byBody, seen = {}, {}
  for _, h in ipairs(hits) do byBody[h.body] = h end
  local lastT, lastRank = -huge, -huge
  for i = 1, n do
    local r = got[i]
    local b = type(r) == 'table' and r.body
    self:check(type(b) == 'table' and self.w.info[b], '%s: record %d has no body: %s', what, i, r)
    self:check(not self:gone(f, b), '%s: record %d is %s, which was removed during the call', what, i, b)
    self:check(not seen[b], '%s: %s twice', what, b)
    seen[b] = true
    local rk = self:rank(b)
    self:check(r.distance > lastT or r.distance == lastT and rk > lastRank, '%s: record %d (%s at %s) out of order',
      what, i, b, r.distance)
    lastT, lastRank = r.distance, rk
    if not self:unsure(f, b) then
      local h = byBody[b]
      self:check(h ~= nil, '%s: record %d is %s at %s, which body:rayCast misses', what, i, b, r.distance)
      self:sameHit(what .. ' record ' .. i, h, b, r.distance, r.x, r.y, r.nx, r.ny, r.shape)
    end
  end
  for _, h in ipairs(hits) do
    self:check(seen[h.body] or self:unsure(f, h.body), '%s: %s (hit at %s) is missing (%d records, the model %d)', what,
      h.body, h.t, n, #hits)
  end
  self:count('rayCastAll hits', n)
  if not out then self:keep(what, got, n) end
end

------------------------------------------------------------------ cast

-- Tolerance of a fraction t of a move of length L, from round-off of the positions.
function P:tolT(L)
  if L == 0 then return 1e-12 end
  return 1e-9 * (self.span + L) / L + 1e-12
end

-- README ("Conventions", Sizes): S.weep, space:cast and space:move keep the moving body's
-- centroid, at the start and at the goal, within REACH - 1 of its sizes (its radius; for a
-- body of none, the length of its move) of the origin along each axis; beyond, they raise an
-- error naming the limit, before anything moves.
function P:outOfRange(body, x0, y0, x1, y1)
  local r = body:getRadius()
  local size = r > 0 and r or sqrt((x1 - x0) ^ 2 + (y1 - y0) ^ 2)
  if size == 0 then return false end
  local lim = (self.space.REACH - 1) * size
  return not (abs(x0) <= lim and abs(y0) <= lim and abs(x1) <= lim and abs(y1) <= lim)
end

-- A goal coordinate at the edge of the range of motion of body b from (x, y) (radius > 0):
-- exactly on it, just beyond it, or well beyond it.
function P:rangeEdge(b, x)
  local lim = (self.space.REACH - 1) * b:getRadius()
  local r, sign = self.rng:next(), x < 0 and -1 or 1
  if r < 0.35 then return sign * lim end
  if r < 0.7 then return sign * lim * (1 + 2 ^ -52) end
  return sign * lim * logRange(self.rng, 1.001, 100)
end

-- The call out of the range of motion raised (r: pcall's results): the error naming the
-- limit, and nothing moved, no game code ran (f: its frame).
function P:rangeError(what, fname, f, r, body, x, y, s, approx)
  self:check(not r[1], '%s: out of the range of motion, and no error', what)
  local e = r[2]
  if isFailure(e) or isBoom(e) then error(e, 0) end
  self:check(type(e) == 'string' and e:find(fname .. ': out of the range of motion', 1, true) and
    e:find('limits.REACH', 1, true), '%s: out of the range of motion, and the error is %s', what, tostring(e))
  local cx, cy = body:getCentroid()
  -- (approx: (x, y) is a copy's centroid, which may differ from the body's in the last place)
  local tol = approx and 1e-12 * (abs(x) + abs(y)) or 0
  self:check(abs(cx - x) <= tol and abs(cy - y) <= tol, '%s: out of the range of motion: the body moved, from (%s, %s)'
    .. ' to (%s, %s)', what, x, y, cx, cy)
  self:check(not f.any and (not s or s.calls == 0), '%s: out of the range of motion: game code ran', what)
  self:count('out-of-range calls')
  self:log('(out of the range of motion: the error)')
end

-- After a cast or move of `body` (its frame f; pcall's results r): docs/space.md ("Your code
-- inside a call"): moving the body that move or cast is moving, from a filter, is an error,
-- raised from the call. A transform of the body as a whole (see push), or a member added to it
-- or removed from it, must raise it; a change of one of its members, or of the body it is a
-- member of, may (the docs leave it open).
-- Returns true when the call raised it; raises the call's other errors.
function P:subjectMoved(what, fname, f, r, body)
  local root = self.rootOf[body]
  -- (a member of the body itself added or removed: the same error, docs/space.md)
  local must = (f.transformed[body] or root and f.transformed[root]) and World.firstLeaf(body) ~= nil
    or f.members[body]
  local may = must or f.moved[body] or f.transformed[body] or root and (f.moved[root] or f.transformed[root])
  if r[1] then
    self:check(not must, '%s: a filter moved the body being moved as a whole, or added or removed a member of it,'
      .. ' and the call raised no error (docs/space.md: an error)', what)
    return false
  end
  local e = r[2]
  if isFailure(e) or isBoom(e) then error(e, 0) end
  if not (may and type(e) == 'string' and e:find(fname .. ': a filter moved the body being moved', 1, true)) then
    self:fail('%s raised %s%s', what, tostring(e), must and ' (a filter moved the body being moved: docs/space.md'
      .. ' promises the error "' .. fname .. ': a filter moved the body being moved")' or '')
  end
  self:count('subject-moved errors')
  self:log('(the error: a filter moved the body being moved)')
  local outer = self.frames[#self.frames]
  if outer and (not self.F.levelsLetGo or outer.kind == 'collisions' and not self.F.caughtInCollisions) then
    -- (caught here, by the game's code another call runs, the error would leave that call's
    -- levels holding what they should let go: see FEATURES.levelsLetGo and
    -- caughtInCollisions; the game passes it on)
    self.nboom = self.nboom + 1
    self:log('(raised again as boom #%d)', self.nboom)
    error(setmetatable({ n = self.nboom }, Boom), 0)
  end
  return true
end

function Q.cast(self, target, X)
  local rng = self.rng
  local E = self.w.entries
  local body, how
  local r = rng:next()
  if #E > 0 and r < 0.75 then
    body = E[rng:int(1, #E)].body
    if body == X then body = nil end -- (its centroid would be read between the change and the cast)
    how = 'in the space'
  elseif r < 0.83 and self.F.memberProbes then
    body, how = self:randomMember(), 'a member of a body in the space'
  end
  if not body then
    local x, y = self.w:randomPoint()
    body, how = self:transient(x, y), 'transient'
  end
  local tx, ty = self:aim(target)
  local cx, cy = body:getCentroid()
  local dx, dy = tx - cx, ty - cy
  if rng:next() < 0.3 or (dx == 0 and dy == 0) then
    local d, a = self.w.s * logRange(rng, 0.05, 6), rng:range(-pi, pi)
    dx, dy = d * cos(a), d * sin(a)
  end
  if rng:next() < 0.02 then dx, dy = 0, 0 end -- (a cast that does not move: what it overlaps)
  -- (to the edge of the range of motion, or beyond)
  if rng:next() < (self.lean.moves and 0.08 or 0.03) and body:getRadius() > 0 then
    if rng:next() < 0.5 then dx = self:rangeEdge(body, dx) - cx else dy = self:rangeEdge(body, dy) - cy end
  end
  local oor = self:outOfRange(body, cx, cy, cx + dx, cy + dy)
  local qf = self:queryFilter(false, body)
  local out, ohow = self:outFor('cast')
  local what = self:fmt('cast(%s %s, %s, %s, %s, %s)', how, body, dx, dy, qf.desc, ohow)
  self:log(what)
  self.casting[body] = (self.casting[body] or 0) + 1
  local f, res = self:probing(body, self.attempt, self, 'cast', self.space.cast, self.space, body, dx, dy, qf.filter,
    out)
  self.casting[body] = self.casting[body] > 1 and self.casting[body] - 1 or nil
  self:release(qf)
  if oor then return self:rangeError(what, 'strike.Space:cast', f, res, body, cx, cy, qf.script) end
  if self:subjectMoved(what, 'strike.Space:cast', f, res, body) then return end
  local hit = res[2]
  if hit then
    self:check(type(hit) == 'table', '%s returned %s', what, hit)
    if out then self:check(hit == out, '%s returned another table than its out', what) end
  else
    self:check(hit == false, '%s returned %s, not false', what, hit)
  end
  if self:probeChanged(f, body) then return end
  local inside = self:E(body)
  local L = sqrt(dx * dx + dy * dy)
  local tolT = self:tolT(L)
  local best, hits = huge, {}
  if not (inside and inside.sensor) then
    for _, e in ipairs(E) do
      if e.body ~= body and not e.sensor and qf.pass(e) and (not inside or f.pf or self:allowed(inside, e)) then
        local h = S.weep(body, dx, dy, e.body)
        if h then
          local copy = { t = h.t, x = h.x, y = h.y, nx = h.nx, ny = h.ny, overlapping = h.overlapping }
          hits[e.body] = copy
          if not self:unsure(f, e.body) and not (inside and f.pf) and h.t < best then best = h.t end
        end
      end
    end
  end
  if not hit then
    self:check(best == huge, '%s: no hit; S.weep hits at t = %s', what, best)
    return
  end
  local b = hit.body
  self:check(type(b) == 'table' and self.w.info[b], '%s: the hit names no body: %s', what, b)
  self:check(not self:gone(f, b), '%s: hit %s, which was removed during the call', what, b)
  self:check(b ~= body, '%s: hit the body cast', what)
  local h = hits[b]
  if self:unsure(f, b) or (inside and f.pf) then
    self:check(hit.t <= best + tolT, '%s: hit %s (changed during the call) at t = %s, after %s', what, b, hit.t, best)
    return
  end
  self:check(h ~= nil, '%s: hit %s at t = %s, which S.weep misses or the model does not allow', what, b, hit.t)
  self:check(h.t <= best + tolT, '%s: hit %s at t = %s; S.weep hits another body first, at %s', what, b, h.t, best)
  self:check(abs(hit.t - h.t) <= tolT, '%s: hit %s at t = %s, S.weep %s', what, b, hit.t, h.t)
  local ptol = 1e-9 * (self.span + L)
  self:check(abs(hit.x - h.x) <= ptol * 10 and abs(hit.y - h.y) <= ptol * 10, '%s: point (%s, %s), S.weep (%s, %s)',
    what, hit.x, hit.y, h.x, h.y)
  self:check(abs(hit.nx - h.nx) <= 1e-6 and abs(hit.ny - h.ny) <= 1e-6, '%s: normal (%s, %s), S.weep (%s, %s)', what,
    hit.nx, hit.ny, h.nx, h.ny)
  self:check(hit.overlapping == h.overlapping, '%s: overlapping %s, S.weep %s', what, hit.overlapping, h.overlapping)
  self:count('cast hits')
end

------------------------------------------------------------------ bodies, count, has, get

function Q.bodies(self)
  local out, how = self:outFor('bodies')
  local what = 'bodies(' .. how .. ')'
  self:log(what)
  local _, got, n = self:within('bodies', self.space.bodies, self.space, out)
  self:listEnd(what, got, n, out)
  local E = self.w.entries
  self:check(n == #E, '%s: %d bodies, the model %d', what, n, #E)
  for i, e in ipairs(E) do
    self:check(got[i] == e.body, '%s: body %d is %s, the model %s', what, i, got[i], e.body)
  end
  self:check(self.space:count() == #E, 'count() is %d, the model %d', self.space:count(), #E)
  for _, e in ipairs(E) do
    self:check(self.space:has(e.body), 'has(%s) is false', e.body)
    local layer, mask, group, sensor = self.space:get(e.body)
    self:check(layer == e.layer and group == e.group and sensor == e.sensor, 'get(%s) gives %s, %s, %s; the model %s,'
      .. ' %s, %s', e.body, layer, group, sensor, e.layer, e.group, e.sensor)
    self:check((mask == nil) == (e.mask == false), 'get(%s): mask %s, the model %s', e.body, mask, e.mask)
  end
  for _, b in ipairs(self.w.pool) do self:check(not self.space:has(b), 'has(%s) is true', b) end
  if not out then self:keep(what, got, n) end
end

------------------------------------------------------------------ collisions and events

-- Every touching pair the model allows now (sensor pairs too), in pair order.
function P:touching()
  local E, list = self.w.entries, {}
  for i = 1, #E do
    local ea = E[i]
    for j = i + 1, #E do
      local eb = E[j]
      if self:allowed(ea, eb) then
        local m = S.triking(ea.body, eb.body)
        if m then
          list[#list + 1] = { a = ea.body, b = eb.body, key = ea.rank * K + eb.rank, sensor = ea.sensor or eb.sensor,
            mtv = m }
        end
      end
    end
  end
  return list
end

function P:pairKey(a, b)
  local ra, rb = self:rank(a), self:rank(b)
  if not (ra and rb) then return nil end
  return ra * K + rb, ra, rb
end

-- Did body b change during the call of frame f (moved, added, removed, given options)?
local function changed(f, b)
  return f.moved[b] or f.added[b] or f.opts[b] or f.removed[b]
end

-- A collisions() call's own pairs as the model sees them when it returns: `cur`, the pairs
-- touching then (byKey: by pair key), `f`, its frame (what changed during it); `oStart`, the
-- serial of the last event before its own events (those before are the rest of the call an
-- error stopped); `memo`, the pairs of each body removed during the call, as they are when it
-- returns (see inList: read when the rest of a call an error stopped runs, calls later, when
-- the other body or the pair filter may have changed since).
function P:segment(f)
  local cur = self:touching()
  local byKey = {}
  for _, p in ipairs(cur) do byKey[p.key] = p end
  local memo, gone = {}, {}
  for b, e in pairs(f.gone) do
    if not self:E(b) then gone[#gone + 1] = e end
  end
  for i, ea in ipairs(gone) do
    for _, eb in ipairs(self.w.entries) do
      local x, y = ea, eb
      if x.rank > y.rank then x, y = y, x end
      memo[x.rank * K + y.rank] = self:allowed(x, y) and S.triking(x.body, y.body) and 'yes' or 'no'
    end
    for j = i + 1, #gone do
      local eb = gone[j]
      memo[ea.rank * K + eb.rank] = self:allowed(ea, eb) and S.triking(ea.body, eb.body) and 'yes' or 'no'
    end
  end
  return { f = f, cur = cur, byKey = byKey, oStart = 0, memo = memo }
end

-- Is the pair `key` (of bodies a, b) in the list the call of segment seg made: 'yes', 'no', or
-- 'maybe' (a body changed during the call: docs/space.md, "bodies added or moved during the
-- call may or may not count for it"). A body removed before the call's own events (before it,
-- by an event of the call before, by the pair filter) is in none of its pairs; one removed
-- during them, and not changed otherwise, is in the pairs it had.
function P:inList(seg, key, a, b)
  local ra, rb = floor(key / K), key % K
  local ga, gb = self.rankGone[ra], self.rankGone[rb]
  if ga and ga <= seg.oStart or gb and gb <= seg.oStart then return 'no' end
  local f = seg.f
  if f.pf or f.moved[a] or f.moved[b] or f.added[a] or f.added[b] or f.opts[a] or f.opts[b] then return 'maybe' end
  if not (f.removed[a] or f.removed[b]) then return seg.byKey[key] and 'yes' or 'no' end
  -- (removed during the events: the pair as it was, by the rule and S.triking)
  local ea, eb = f.gone[a] or self:E(a), f.gone[b] or self:E(b)
  if not (ea and eb and ea.rank == ra and eb.rank == rb) then return 'maybe' end
  return seg.memo[key] or 'maybe'
end

-- What a failing interpretation of a call's events raises (see checkEvents).
local Trial = {}

-- The events log[i0..i1]: one part of the sequence of events of the call of segment seg -- the
-- rest of a call an error stopped, or a call's own -- going on after position ptr ({sec = 0 for
-- the ends, 1 for begin and stay; key}, or nil). docs/space.md ("Sensors and events", Events):
-- first 'end' for every pair that touched at the previous call and no longer does, in pair
-- order, then 'begin' or 'stay' for each pair touching, in pair order; balanced against `open`
-- (updated): a pair begins once, stays and ends only after it began, ends once. Pairs that
-- surely touch have the MTV and contacts of S.triking and S.ite. With `complete` (the part ran
-- to its end; else up to its last event), every event due was delivered: an end for each pair
-- begun that surely left the list, a begin or stay for each pair surely in it, unless a body of
-- the pair was removed before its turn (`serial0`: the serial before the part's first event).
-- Returns the position of the last event.
function P:validatePart(bad, seg, evs, i0, i1, ptr, open, complete, serial0)
  local sec, key = -1, -1
  if ptr then sec, key = ptr.sec, ptr.key end
  local moved = self.curFrame.moved -- (the contacts of an event, recomputed when it runs, are S.ite's when
  -- neither body moved during the call that delivers it)
  local got, marks = {}, {}
  for i = i0, i1 do
    local ev = evs[i]
    local a, b, E = ev.a, ev.b, ev.event
    local esec, k
    if E == 'end' then
      -- (the pair ending may be one of a body removed and added again since: the open pair of
      -- these two bodies in this order, the earliest)
      esec = 0
      for k2, p in pairs(open) do
        if p.a == a and p.b == b and (not k or k2 < k) then k = k2 end
      end
      if not k then bad(i, 'event %d: end %s-%s, which never began (or ended already)', i, a, b) end
    else
      esec, k = 1, ev.key
    end
    if esec < sec or esec == sec and k <= key then
      bad(i, 'event %d, %s %s-%s, out of order (ends first, then begin and stay, each in pair order; a pair once)%s',
        i, E, a, b, i == i0 and ptr and ' after the events of the call it goes on with' or '')
    end
    sec, key = esec, k
    marks[#marks + 1] = { sec = esec, key = k, serial = ev.serial }
    local st = self:inList(seg, k, a, b)
    if E == 'end' then
      if st == 'yes' then bad(i, 'event %d: end %s-%s, which still touches', i, a, b) end
      open[k] = nil
    else
      if st == 'no' then bad(i, 'event %d: %s %s-%s; the model has no such pair', i, E, a, b) end
      if E == 'begin' then
        if open[k] then bad(i, 'event %d: begin %s-%s, which began before and never ended', i, a, b) end
        open[k] = { a = a, b = b }
      elseif not open[k] then
        bad(i, 'event %d: stay %s-%s, which never began', i, a, b)
      end
      got[k] = true
      local p = st == 'yes' and seg.byKey[k] -- (none for a body removed since: see inList)
      if p then
        if ev.sensor ~= p.sensor then bad(i, 'event %d (%s %s-%s): record.sensor %s', i, E, a, b, ev.sensor) end
        if p.sensor then
          if ev.mtv ~= false then bad(i, 'event %d (%s %s-%s): a sensor pair with mtv %s', i, E, a, b, ev.mtv) end
        else
          if not mtvMatches(ev.mtv, p.mtv) then
            bad(i, 'event %d (%s %s-%s): mtv %s, S.triking %s%s', i, E, a, b, ev.mtv, p.mtv,
              ptr and ' (when the call it goes on with ran)' or '')
          end
          if not (moved[a] or moved[b]) then
            -- (S.ite may find none for a pair touching within round-off: nil)
            local e = S.ite(p.mtv)
            local ne = e and e.count or 0
            if not (ev.ncontacts == ne or ev.ctype == 'nil' and ne == 0) then
              bad(i, 'event %d (%s %s-%s): %s contacts, S.ite %d', i, E, a, b, ev.ncontacts or ev.ctype, ne)
            end
          end
        end
      end
    end
  end
  -- what was due before the end of the part and is missing
  local function due(s, k)
    if ptr and (s < ptr.sec or s == ptr.sec and k <= ptr.key) then return false end
    return complete or s < sec or s == sec and k < key
  end
  local ends = {}
  for k in pairs(open) do
    if due(0, k) then ends[#ends + 1] = k end
  end
  table.sort(ends)
  for _, k in ipairs(ends) do
    local p = open[k]
    if self:inList(seg, k, p.a, p.b) == 'no' then
      bad(i1 + 1, '%s-%s no longer touches (or is no longer a pair), and got no end%s', p.a, p.b,
        complete and '' or ' before the error')
    end
  end
  local j, last = 1, serial0
  for _, p in ipairs(seg.cur) do
    local k = p.key
    while marks[j] and (marks[j].sec < 1 or marks[j].key < k) do
      last = marks[j].serial
      j = j + 1
    end
    if not got[k] and due(1, k) and self:inList(seg, k, p.a, p.b) == 'yes' then
      -- (its turn came after event `last`: a body removed before then is no longer in the pair)
      local ga, gb = self.rankGone[floor(k / K)], self.rankGone[k % K]
      if not (ga and ga <= last or gb and gb <= last) then
        bad(i1 + 1, '%s-%s touches, and got no begin or stay%s', p.a, p.b, complete and '' or ' before the error')
      end
    end
  end
  return sec >= 0 and { sec = sec, key = key } or ptr
end

-- One interpretation of the events of a collisions() call: log[1..s] go on with the call H
-- (a pending one: see checkEvents) and the rest are the call's own. Raises a Trial when they
-- do not fit; else returns the pairs open after them and what the call leaves for the next.
function P:tryEvents(ctx, seg, H, s, outcome)
  local evs, m = ctx.log, #ctx.log
  local function bad(at, fmt, ...)
    error(setmetatable({ at = at, msg = self:fmt(fmt, ...) }, Trial), 0)
  end
  local open = {}
  for k, p in pairs(self.open) do open[k] = p end
  local pend
  if H then
    -- (an error in the part that goes on: s = m, and the rest of H is still to come)
    local partial = outcome == 'callback' and s == m
    local at = self:validatePart(bad, H.seg, evs, 1, s, H.ptr, open, not partial, ctx.base)
    if partial then pend = { seg = H.seg, ptr = at } end
  elseif s ~= 0 then
    bad(1, 'internal: no call to go on with')
  end
  if not pend then
    if outcome == 'pf' then
      -- (docs/space.md, "Your code inside a call", Errors: an error in the pair filter forgets
      -- that call's pairs)
      if s < m then bad(s + 1, 'event %d (%s %s-%s): an event of a call whose pair filter raised an error', s + 1,
        evs[s + 1].event, evs[s + 1].a, evs[s + 1].b) end
    else
      if outcome == 'callback' and s == m then bad(m + 1, 'a callback raised an error, and no event was running') end
      local own = { f = seg.f, cur = seg.cur, byKey = seg.byKey, oStart = ctx.base + s, memo = seg.memo }
      local at = self:validatePart(bad, own, evs, s + 1, m, nil, open, outcome == 'completed', ctx.base + s)
      if outcome == 'callback' then pend = { seg = own, ptr = at } end
    end
  end
  return { open = open, pend = pend, s = H and s or 0 }
end

-- The events of a collisions() call against the model. A call an error stopped in a callback
-- leaves the rest of its events for the next call (docs/space.md, Errors), which runs them
-- first, then its own: the next call's log is a part of the old call's sequence followed by a
-- sequence of its own. Where one ends is not always known (a pair that changed during the old
-- call may or may not be in its rest), so every split is tried, and every call an error stopped
-- that fits is kept as a possible state for the next one.
function P:checkEvents(what, ctx, outcome, seg)
  local evs, m = ctx.log, #ctx.log
  local hyps = #self.pends > 0 and self.pends or { false }
  local results, best = {}, nil
  self.curFrame = ctx.frame
  for _, H in ipairs(hyps) do
    for s = 0, H and m or 0 do
      local ok, res = pcall(self.tryEvents, self, ctx, seg, H, s, outcome)
      if ok then
        results[#results + 1] = res
      elseif getmetatable(res) == Trial then
        if not best or res.at > best.at then best = res end
      else
        error(res, 0)
      end
    end
  end
  self.curFrame = nil
  if #results == 0 then
    self:fail('%s: %s%s', what, best.msg, #self.pends > 0 and ' (events of the call an error stopped come first)' or '')
  end
  self.open = results[1].open
  -- (every distinct one, none left out: a call an error stopped in the middle of the rest of
  -- another leaves one per split that fits; up to 5 at once, seed 3's program 359)
  local pends, seen = {}, {}
  for _, r in ipairs(results) do
    local p = r.pend
    if p then
      local byF = seen[p.seg.f] or {}
      seen[p.seg.f] = byF
      local id = ('%.0f:%.0f:%.0f'):format(p.seg.oStart, p.ptr and p.ptr.sec or -1, p.ptr and p.ptr.key or -1)
      if not byF[id] then
        byF[id] = true
        pends[#pends + 1] = p
      end
    end
  end
  self.pends = pends
  for _, ev in ipairs(evs) do self:count('events ' .. ev.event) end
  if hyps[1] then self:count('resumed events', results[1].s) end
  if outcome == 'callback' then self:count('collisions stopped in a callback') end
  if outcome == 'pf' then self:count('collisions stopped in the pair filter') end
end

function Q.collisions(self)
  local out, how = self:outFor('collisions')
  local what = 'collisions(' .. how .. ')'
  self:log(what)
  if self.collCtx[#self.collCtx] then -- (a collisions() from inside another one of the same
    -- space: docs/space.md, "Your code inside a call", says it is an error, raised at the
    -- calling line, that changes nothing)
    self:count('collisions inside collisions')
    local ok, err = pcall(self.space.collisions, self.space, out)
    if ok or type(err) ~= 'string' or not err:find('strike.Space:collisions: called from the pair filter or an'
      .. ' event callback of the same space\'s collisions()', 1, true) then
      self:fail('%s from inside collisions(): expected the error docs/space.md promises, got %s', what,
        ok and 'no error' or tostring(err))
    end
    return
  end
  self.serials.collisions = self.serials.collisions + 1
  local f = self:push('collisions')
  local ctx = { log = {}, frame = f, base = self.evSerial, cur = self.carry or nil, raised = false }
  self.carry = false
  self.collCtx[#self.collCtx + 1] = ctx
  local r = pack(pcall(self.space.collisions, self.space, out))
  self.collCtx[#self.collCtx] = nil
  self:pop(f)
  local outcome = 'completed'
  if not r[1] then
    if isFailure(r[2]) then error(r[2], 0) end
    if not isBoom(r[2]) then self:fail('%s raised an error no script raised: %s', what, tostring(r[2])) end
    outcome = ctx.raised
    if not outcome then
      self:fail('%s raised %s, which came neither from its pair filter nor from a callback', what, tostring(r[2]))
    end
  end
  local seg = (outcome == 'completed' or self.events) and self:segment(f)
  if outcome == 'completed' then self:checkList(what, f, seg, r[2], r[3], out) end
  if self.events then
    if outcome == 'callback' then
      self:check(ctx.cur ~= nil, '%s: a callback raised an error, and no event was running', what)
      ctx.cur.carried = true
      self.carry = ctx.cur
    else
      self:finishEvent(ctx)
    end
    self:checkEvents(what, ctx, outcome, seg)
  end
  if not r[1] then error(r[2], 0) end
end

-- collisions()' list: every solid pair the model has, in pair order, none of a body removed
-- during the call (docs/space.md, "Your code inside a call": a body removed during a call never
-- appears in its results; the list is compacted after the events).
function P:checkList(what, f, seg, got, n, out)
  self:listEnd(what, got, n, out)
  local cur, curKey = seg.cur, seg.byKey
  local function pairUnsure(a, b) return f.pf or changed(f, a) or changed(f, b) end
  local last, seen = -1, {}
  for i = 1, n do
    local rec = got[i]
    self:check(type(rec) == 'table' and self.w.info[rec.a] and self.w.info[rec.b], '%s: record %d is %s', what, i,
      rec)
    local a, b = rec.a, rec.b
    self:check(not (self:gone(f, a) or self:gone(f, b)), '%s: record %d, %s-%s: a body removed during the call',
      what, i, a, b)
    local key, ra, rb = self:pairKey(a, b)
    self:check(key, '%s: record %d, %s-%s: a body not in the space', what, i, a, b)
    self:check(rec.sensor == false, '%s: record %d (%s-%s): sensor is %s', what, i, a, b, rec.sensor)
    self:check(ra < rb, '%s: record %d is %s-%s, b added before a', what, i, a, b)
    self:check(key > last, '%s: record %d (%s-%s) out of pair order', what, i, a, b)
    last = key
    seen[key] = true
    if not pairUnsure(a, b) then
      local p = curKey[key]
      self:check(p and not p.sensor, '%s: record %d is %s-%s; the model does not have that pair', what, i, a, b)
      self:check(mtvMatches(rec.mtv, p.mtv), '%s: record %d (%s-%s): mtv %s, S.triking %s', what, i, a, b, rec.mtv,
        p.mtv)
      if self.events then
        -- (S.ite may find none for a pair touching within round-off: nil)
        local c = rec.contacts
        local e = S.ite(p.mtv)
        local ne = e and e.count or 0
        self:check(type(c) == 'table' and c.count == ne or c == nil and ne == 0, '%s: record %d (%s-%s): %s'
          .. ' contacts, S.ite %d', what, i, a, b, type(c) == 'table' and c.count or c, ne)
      else
        self:check(rec.contacts == nil, '%s: record %d: contacts without callbacks', what, i)
      end
    end
  end
  for _, p in ipairs(cur) do
    if not p.sensor and not pairUnsure(p.a, p.b) then
      self:check(seen[p.key], '%s: %s-%s is missing, S.triking %s deep (%d records; the model %d pairs, sensors'
        .. ' included)', what, p.a, p.b, p.mtv.depth, n, #cur)
    end
  end
  self:count('colliding pairs', n)
  self:keep(what, got, n, 'collisions')
end

------------------------------------------------------------------ move

-- Who a move of M meets: the pair rule (M in the space), not a sensor, and the filter's
-- response ('slide' without one).
function P:moveResponse(plan, e)
  if e.sensor then return nil end
  if not self:allowed(plan.Me, e) then return nil end
  if plan.script then return self:moveResp(plan.script, e.body) end
  return 'slide'
end

local PASS = { cross = true, passer = true }
local ONE_LEAF = { shape = true, single = true, transient = true }
local SOLID = { slide = true, touch = true, bounce = true, stopper = true }

-- A random move of M (a body in the space) toward the target (or nearby), with a filter and
-- the character options sometimes.
function P:planMove(M, target)
  local rng, w = self.rng, self.w
  local plan = { M = M, fc = {}, pfc = {} }
  if target then
    plan.gx, plan.gy = target[1] + w.s * rng:range(-0.5, 0.5), target[2] + w.s * rng:range(-0.5, 0.5)
  else
    local cx, cy = M:getCentroid()
    local d, a = w.s * logRange(rng, 0.02, 8), rng:range(-pi, pi)
    plan.gx, plan.gy = cx + d * cos(a), cy + d * sin(a)
    if rng:next() < 0.3 then plan.gx, plan.gy = self:aim() end
  end
  local far = rng:next() < (self.lean.moves and 0.05 or 0.015) and M:getRadius() > 0
  if far then -- (beyond the edge of the range of motion)
    -- (by more than a rounding: the move's checks read a copy of a body changed just before,
    -- whose radius may differ from the body's in the last place; casts test the very edge)
    local lim = (self.space.REACH - 1) * M:getRadius()
    local x = rng:next() < 0.5 and -lim or lim
    x = rng:next() < 0.5 and x * (1 + 1e-9) or x * logRange(rng, 1.001, 100)
    if rng:next() < 0.5 then plan.gx = x else plan.gy = x end
  end
  if rng:next() < 0.6 then
    plan.script = self:newScript('move', false, M)
    plan.filter = self:moveFilterFn(plan.script, plan)
  end
  local acts = plan.script and #plan.script.actions > 0
  local lean = self.lean.moves
  if rng:next() < ((acts or lean) and 0.7 or 0.45) then
    local opts = {}
    if rng:next() < (lean and 0.95 or 0.8) then opts.snap = w.s * logRange(rng, 0.05, 2) end
    if rng:next() < ((acts or lean) and 0.9 or 0.7) then opts.slope = rng:range(0.2, 1.3) end
    if rng:next() < 0.3 then
      local a = rng:range(-pi, pi)
      opts.up = { cos(a), sin(a) }
    end
    if rng:next() < 0.3 then opts.step = w.s * logRange(rng, 0.05, 1) end
    plan.opts = opts
    if lean and opts.snap and not far then
      -- (a move that does not go up, which the snap check needs: toward a body below the
      -- start, where there is ground; else the goal mirrored when it is above the start)
      local ux, uy = 0, -1
      if opts.up then ux, uy = opts.up[1], opts.up[2] end
      local cx, cy = M:getCentroid()
      local E = self.w.entries
      for _ = 1, 4 do
        local b = #E > 0 and E[rng:int(1, #E)].body
        if b and b ~= M and (not b.shapes or b:getShapeCount() > 0) then
          local bx, by = b:getCentroid()
          if (bx - cx) * ux + (by - cy) * uy < 0 then
            plan.gx, plan.gy = bx, by
            break
          end
        end
      end
      local d = (plan.gx - cx) * ux + (plan.gy - cy) * uy
      if d > 0 then plan.gx, plan.gy = plan.gx - 2 * d * ux, plan.gy - 2 * d * uy end
    end
  end
  return plan
end

-- The state a move starts from: for every other body, whether M overlaps it (the MTV) and
-- S.weep of M along the first leg. `sub` maps a body changed just before the move to its
-- copy changed the same way (read instead of it, so that nothing reads the changed body).
function P:movePre(plan, sub)
  local M = plan.M
  local Mg = sub and sub[M] or M
  local cx, cy = Mg:getCentroid()
  local pre = { cx = cx, cy = cy, dx = plan.gx - cx, dy = plan.gy - cy, size = Mg:getRadius(), mtv = {}, weep = {},
    bodies = {} }
  pre.x0, pre.y0, pre.x1, pre.y1 = Mg:getBounds()
  -- (the skin: space.SKIN times its radius, or for a body of none the length of its move)
  pre.skin = self.space.SKIN * (pre.size > 0 and pre.size or sqrt(pre.dx * pre.dx + pre.dy * pre.dy))
  for _, e in ipairs(self.w.entries) do
    local b = e.body
    if b ~= M then
      local bg = sub and sub[b] or b
      pre.bodies[#pre.bodies + 1] = b
      local m = S.triking(Mg, bg)
      if m then
        pre.mtv[b] = { nx = m.nx, ny = m.ny, depth = m.depth,
          chain = m.colliderShape.kind == 'chain' or m.collidedShape.kind == 'chain' }
      elseif pre.dx ~= 0 or pre.dy ~= 0 then
        local h = S.weep(Mg, pre.dx, pre.dy, bg)
        if h then pre.weep[b] = { t = h.t, nx = h.nx, ny = h.ny, overlapping = h.overlapping } end
      end
    end
  end
  return pre
end

local function optsDesc(o)
  if not o then return 'nil' end
  local parts = {}
  for _, k in ipairs({ 'snap', 'slope', 'step' }) do
    if o[k] then parts[#parts + 1] = k .. '=' .. g(o[k]) end
  end
  if o.up then parts[#parts + 1] = ('up={%s,%s}'):format(g(o.up[1]), g(o.up[2])) end
  return '{' .. table.concat(parts, ' ') .. '}'
end

function Q.move(self, target, _, sub, plan)
  local E = self.w.entries
  if not plan and not target and self.lean.moves and self.rng:next() < 0.25 then plan = self:walkPlan() end
  if not plan then
    if #E == 0 then return end
    local M
    for _ = 1, 4 do
      M = E[self.rng:int(1, #E)].body
      if not self.moving[M] and (self.F.touchProbe or not self.probes[M]) then break end
      M = nil
    end
    if not M then return end
    plan = self:planMove(M, target)
  end
  local M = plan.M
  local Mg = sub and sub[M] or M
  local x0, y0 = Mg:getCentroid()
  local oor = self:outOfRange(Mg, x0, y0, plan.gx, plan.gy)
  local pre = not oor and self:movePre(plan, sub)
  plan.Me = self:E(M)
  local what = self:fmt('move(%s, %s, %s, %s, %s) from (%s, %s)', M, plan.gx, plan.gy,
    plan.script and self:describeScript(plan.script) or 'nil', optsDesc(plan.opts), x0, y0)
  self:log(what)
  if not oor then self:effect('moved', M) end -- (for the calls this move runs in)
  self.serials.move = self.serials.move + 1
  self.moving[M] = (self.moving[M] or 0) + 1
  plan.depth, plan.pf0 = #self.frames + 1, self.pf
  self.movePlans[#self.movePlans + 1] = plan
  local f, r = self:attempt('move', self.space.move, self.space, M, plan.gx, plan.gy, plan.filter, plan.opts)
  self.movePlans[#self.movePlans] = nil
  self.moving[M] = self.moving[M] > 1 and self.moving[M] - 1 or nil
  if plan.filter then self.deadFns[plan.filter] = 'the move filter ' .. plan.script.tag end
  if oor then return self:rangeError(what, 'strike.Space:move', f, r, M, x0, y0, plan.script, Mg ~= M) end
  if self:subjectMoved(what, 'strike.Space:move', f, r, M) then return end
  self:checkMove(what, plan, pre, f, r[2], r[3], r[4], r[5])
end

-- Where the first leg of a move stops before body b, which S.weep meets at t with normal
-- (nx, ny): half a skin short of the touch along the normal, taken back along the leg, never
-- before its start (docs/moving.md, "The stop and the skin"); returns that fraction of the leg.
local function stopAt(pre, t, nx, ny)
  local dn = -(pre.dx * nx + pre.dy * ny)
  if dn > 0 then t = t - pre.skin * 0.5 / dn end
  return t > 0 and t or 0
end

-- An exact fit (docs/moving.md, "Moving bodies in a space", Exact fits): a leg that meets a
-- body only because at its stop there the moving body's box overlaps that body's box across by
-- at most the skin goes on from the stop, shifted across by the overlap (at most the skin), and
-- that body is not reported. Then the first collision reported is on the next leg: its t is a
-- fraction of that leg. May the first collision c1 (with o, which S.weep meets at t) come after
-- such fits? Every body S.weep meets before o must be one the box overlaps across by at most
-- the skin at the stop before it, o too when c1 is not at its S.weep time, and c1's stop must
-- be where the first leg would stop before o, give or take the shifts. A body removed during
-- the move (frame f) may have been such a fit before it went.
function P:afterFit(pre, f, sureHits, o, t, c1, tolT)
  local slack = 1e-9 * (self.span + abs(pre.dx) + abs(pre.dy))
  local function fits(b, tb)
    local h = pre.weep[b]
    if not h or h.overlapping then return false end
    local ts = stopAt(pre, tb, h.nx, h.ny)
    local mx, my = ts * pre.dx, ts * pre.dy
    local ax0, ay0, ax1, ay1 = pre.x0 + mx, pre.y0 + my, pre.x1 + mx, pre.y1 + my
    local ox0, oy0, ox1, oy1 = b:getBounds()
    for _, ov in ipairs({ ox1 - ax0, ax1 - ox0, oy1 - ay0, ay1 - oy0 }) do
      if ov > -slack and ov <= pre.skin + slack then return true end
    end
    return false
  end
  local any = false
  for b, tb in pairs(sureHits) do
    if tb < t - tolT or b == o then
      if fits(b, tb) then any = true elseif b ~= o then return false end
    end
  end
  -- (a body the move's filter removed during it, met on the first leg before o: the leg may
  -- have gone on past it as an exact fit before it was removed)
  for _, b in ipairs(pre.bodies) do
    local h = pre.weep[b]
    if f.removed[b] and not (f.moved[b] or f.added[b] or f.opts[b]) and h and h.t < t - tolT and fits(b, h.t) then
      any = true
    end
  end
  if not any then return false end
  local h = pre.weep[o]
  if not h then return false end
  local ts = stopAt(pre, t, h.nx, h.ny)
  local px, py = pre.cx + ts * pre.dx, pre.cy + ts * pre.dy
  return abs(c1.touchX - px) <= 2 * pre.skin + slack and abs(c1.touchY - py) <= 2 * pre.skin + slack
end

function P:checkMove(what, plan, pre, f, ax, ay, cols, k)
  local M, Me = plan.M, plan.Me
  local function colsDesc()
    local parts = {}
    for i = 1, k do
      local c = cols[i]
      parts[#parts + 1] = self:fmt('%s %s t=%s n=(%s, %s) touch=(%s, %s)%s', c.other, c.type, c.t, c.nx, c.ny,
        c.touchX, c.touchY, c.overlapping and ' overlapping' or '')
    end
    return k .. ' collisions: ' .. table.concat(parts, '; ')
  end
  self:check(type(ax) == 'number' and type(ay) == 'number' and type(cols) == 'table' and type(k) == 'number',
    '%s returned %s, %s, %s, %s', what, ax, ay, cols, k)
  self:check(cols[k + 1] == nil, '%s: %d collisions, and %s after them', what, k, cols[k + 1])
  local cx, cy = M:getCentroid()
  local ptol = 1e-9 * (self.span + abs(pre.dx) + abs(pre.dy))
  self:check(abs(cx - ax) <= ptol and abs(cy - ay) <= ptol, '%s: returned (%s, %s), the body is at (%s, %s)', what, ax,
    ay, cx, cy)
  local L = sqrt(pre.dx * pre.dx + pre.dy * pre.dy)
  if Me.sensor and not f.opts[M] then
    self:check(k == 0 and ax == plan.gx and ay == plan.gy, '%s: a sensor moves straight to its goal; it reached'
      .. ' (%s, %s) with %d collisions', what, ax, ay, k)
    return
  end
  -- every collision: a body of the space (or one removed during the move, met before that),
  -- allowed, with the filter's response, once when it passes through
  local onceSeen, reports = {}, {}
  for i = 1, k do
    local col = cols[i]
    local o = type(col) == 'table' and col.other
    self:check(type(o) == 'table' and self.w.info[o], '%s: collision %d names no body: %s', what, i, o)
    self:check(o ~= M, '%s: collision %d is with the body moved', what, i)
    reports[o] = (reports[o] or 0) + 1
    if f.removed[o] then
      -- (docs/moving.md, "Moving bodies in a space": a body the filter removes is not met after
      -- that.) A body removed during the move was met at most once per time the move could meet
      -- it: a call of its filter, or else of the pair filter, that returned with it still in
      -- the space. With neither, only the responses, which run after a meeting, could remove
      -- it.
      local chances = huge
      if plan.script then
        chances = plan.fc[o] or 0
      elseif plan.pf0 and not f.pf then
        chances = plan.pfc[o] or 0
      end
      -- (Added again since: a new body, which may or may not count for the move: docs/space.md,
      -- "Your code inside a call".)
      self:check(f.added[o] or reports[o] <= chances or not self.F.strictRemoved, '%s: collision %d is with %s,'
        .. ' which was removed (during the move) before it was met', what, i, o)
    else
      self:check(self:E(o) ~= nil, '%s: collision %d is with %s, which is not in the space', what, i, o)
    end
    local e = self:E(o)
    if e and not (f.pf or f.opts[o] or f.opts[M] or f.added[o] or f.removed[o]) then -- (the rule as it was)
      self:check(not e.sensor, '%s: collision %d is with the sensor %s', what, i, o)
      self:check(self:allowed(Me, e), '%s: collision %d is with %s, which the pair rule forbids', what, i, o)
    end
    local want = plan.script and self:moveResp(plan.script, o) or 'slide'
    self:check(col.type == want, '%s: collision %d with %s has type %s; the filter says %s', what, i, o, col.type, want)
    if PASS[want] then
      -- (the snap, a cast of its own after the legs and the move's last collision, where it
      -- ended, may land on a body met with a response of the game's: docs/moving.md, "Moving
      -- bodies in a space")
      local snap = want ~= 'cross' and i == k and plan.opts and plan.opts.snap
        and plan.opts.snap > 0 and col.touchX == ax and col.touchY == ay
      self:check(not onceSeen[o] or snap, '%s: %s (%s) met twice in one move; %s', what, o, want, colsDesc())
      onceSeen[o] = true
    end
    local nl = sqrt(col.nx * col.nx + col.ny * col.ny)
    self:check(abs(nl - 1) <= 1e-9, '%s: collision %d: the normal (%s, %s) is not a unit vector', what, i, col.nx,
      col.ny)
    self:check(col.t >= 0 and col.t <= 1 + 1e-12, '%s: collision %d: t = %s', what, i, col.t)
  end
  self:count('move collisions', k)
  self:keep(what, cols, k, 'move')
  -- no live-lock: a move does not go on meeting the same body at t = 0 without moving (the
  -- issue: a cap on a move's legs never leaves a body short of where its responses take it).
  -- (A body that starts inside several bodies whose responses turn it from one into the
  -- next, bouncing, may meet them in turn without moving until the cap: it is trapped.)
  local run, longest = 0, 0
  for i = 1, k do
    local c, p = cols[i], cols[i - 1]
    if c.t == 0 and p and p.t == 0 and c.other == p.other and c.touchX == p.touchX and c.touchY == p.touchY then
      run = run + 1
      if run > longest then longest = run end
    else
      run = 0
    end
  end
  if not f.any and self.F.stuck then
    self:check(longest < 8,
      '%s: stuck: %d legs in a row meet the same body at t = 0 and go nowhere (%d collisions); %s',
      what, longest + 1, k, colsDesc())
  end
  if f.pf or f.opts[M] or L == 0 then return end
  -- the model's first leg: the earliest S.weep hit among the bodies the move may meet (a
  -- body overlapping at the start counts at t = 0 when the move goes further into it; ASSUMED
  -- unsure: a chain in the overlap, a move along the overlap's normal)
  local tolT = self:tolT(L)
  local roundoff = 1e-10 * (self.span + L)
  -- (docs/moving.md: a body overlapping at the start counts when the move goes further in by
  -- more than space.INTO of its length plus the rounding of its coordinates, 2^-48 of the
  -- largest; within twice that, either way)
  local grain = 2 * (self.space.INTO * L + 2 ^ -48 * (self.span + self.w:side() + L))
  local best, sureHits, unsureB = huge, {}, {}
  for _, b in ipairs(pre.bodies) do
    local e = self:E(b)
    local resp = e and self:moveResponse(plan, e)
    local ch = f.moved[b] or f.added[b] or f.opts[b] or f.removed[b]
    if resp or ch then
      local m, h = pre.mtv[b], pre.weep[b]
      local t, sure = nil, not ch
      if m then
        local dn = (pre.dx * m.nx + pre.dy * m.ny) / L
        -- (or touching, within round-off; or going in by no more than the grain)
        if m.chain or abs(dn) <= 1e-9 or m.depth <= roundoff or abs(dn) * L <= grain then
          t, sure = 0, false
        elseif dn > 0 then
          t = 0
        end
      elseif h then
        t = h.t
      end
      if ch then
        unsureB[b] = -huge -- (moved or changed during the move: met at any time)
      elseif t then
        if sure then
          sureHits[b] = t
          if t < best then best = t end
        else
          unsureB[b] = t
        end
      end
    end
  end
  -- (a body added during the move, by a filter: met at any time, or not)
  for b in pairs(f.added) do unsureB[b] = -huge end
  local snaps = plan.opts and plan.opts.snap and plan.opts.snap > 0
  local up = plan.opts and plan.opts.up
  local ux, uy = 0, -1
  if up then
    local l = sqrt(up[1] * up[1] + up[2] * up[2])
    ux, uy = up[1] / l, up[2] / l
  end
  local rising = pre.dx * ux + pre.dy * uy > 0
  if k == 0 then
    if best < huge then
      local who
      for _, b in ipairs(pre.bodies) do
        if sureHits[b] == best then
          who = b
          break
        end
      end
      self:fail('%s: no collision; S.weep meets %s at t = %s on the way', what, who, best)
    end
    self:check(ax == plan.gx and ay == plan.gy, '%s: no collision, and it ended at (%s, %s), not at its goal', what, ax,
      ay)
  else
    local c1 = cols[1]
    local o = c1.other
    if best == huge then
      self:check(unsureB[o] or (snaps and not rising and k == 1), '%s: the first collision is with %s at t = %s;'
        .. ' S.weep meets nothing on the first leg', what, o, c1.t)
    else
      local t = sureHits[o]
      local first
      for _, b in ipairs(pre.bodies) do
        if sureHits[b] == best then
          first = b
          break
        end
      end
      local how = first and pre.mtv[first] and self:fmt(' (overlapping it %s deep at the start, moving further in)',
        pre.mtv[first].depth) or ''
      if t and not (t <= best + tolT and abs(c1.t - t) <= tolT) and self:afterFit(pre, f, sureHits, o, t, c1, tolT) then
        self:count('first collisions after an exact fit')
      elseif t then
        self:check(t <= best + tolT, '%s: the first collision is with %s (S.weep t = %s); S.weep meets %s first, at'
          .. ' t = %s%s; %s', what, o, t, first, best, how, colsDesc())
        self:check(abs(c1.t - t) <= tolT, '%s: the first collision (%s) at t = %s, S.weep %s', what, o, c1.t, t)
      else
        self:check(unsureB[o] and unsureB[o] <= best + tolT, '%s: the first collision is with %s at t = %s; S.weep'
          .. ' meets %s first (t = %s%s); %s', what, o, c1.t, first, best, how, colsDesc())
      end
    end
  end
  -- passing through: with nothing solid on the line, the body ends at its goal and every
  -- body crossed is reported once
  if next(unsureB) == nil and not (snaps and not rising) and not f.any then
    local allPass = true
    for _, b in ipairs(pre.bodies) do
      -- (a solid body the move starts inside and leaves along its MTV there is no hit of the
      -- first leg; a later leg, after a collision, may start inside it still and go further
      -- in along its MTV then: met)
      if (sureHits[b] or pre.mtv[b] and k > 0) and not PASS[self:moveResponse(plan, self:E(b))] then
        allPass = false
      end
    end
    if allPass then
      self:check(ax == plan.gx and ay == plan.gy, '%s: everything on the way is passed through (%d bodies), yet it'
        .. ' ended at (%s, %s), not at its goal', what, k, ax, ay)
      for _, b in ipairs(pre.bodies) do
        local t = sureHits[b]
        if t and t < 1 - tolT then
          self:check(reports[b] == 1, '%s: %s (t = %s) is passed through, and reported %d times', what, b, t,
            reports[b] or 0)
        end
      end
      self:count('moves through everything')
      if k >= 64 then self:count('moves through 64 or more') end
    end
  end
  -- the end: clear of every solid body it was clear of at the start (ASSUMED: chain members
  -- excepted, a body passes a one-way platform from behind; and a depth within round-off of
  -- the coordinates: a move that grazes a corner, which S.weep does not count as a hit, may
  -- end a rounding inside it -- the numeric range is spec'd elsewhere)
  for _, b in ipairs(pre.bodies) do
    local e = self:E(b)
    if e and not pre.mtv[b] and not (f.moved[b] or f.added[b] or f.opts[b]) then
      local resp = self:moveResponse(plan, e)
      if SOLID[resp] then
        local m = S.triking(M, b)
        if m and m.depth > roundoff and m.colliderShape.kind ~= 'chain' and m.collidedShape.kind ~= 'chain' then
          self:fail('%s: it ended %s deep in %s (%s), which it started clear of; %s', what, m.depth, b, resp,
            colsDesc())
        end
      end
    end
  end
  -- the skin: it never rests exactly touching a solid body it met ("space:move stops a skin
  -- short of what it meets, so the body never rests exactly touching"; but a leg that starts
  -- touching, t = 0, stops where it starts: "never before its start"; chains are one-sided;
  -- and for bodies of one leaf each: a compound met through one member may end touching
  -- another that the move only grazed, which is no hit)
  local atStart = {}
  for i = 1, k do
    if cols[i].t <= 0 then atStart[cols[i].other] = true end
  end
  local info = self.w.info
  for i = 1, k do
    local o = cols[i].other
    if SOLID[cols[i].type] and self:E(o) and not pre.mtv[o] and not (f.moved[o] or f.added[o] or f.opts[o])
      and not atStart[o] and ONE_LEAF[info[M].kind] and ONE_LEAF[info[o].kind] then
      local d = S.eparation(M, o)
      self:check(d > 0, '%s: it rests %s from %s, which it met (collision %d): touching, not a skin away; %s', what, d,
        o, i, colsDesc())
    end
  end
  -- snap: a move that does not go up ends on walkable ground within snap below it, when
  -- there is some (checked with a slope: docs/moving.md defines walkable by it)
  if snaps and not rising and plan.opts.slope and not f.any then
    local snap, c = plan.opts.snap, cos(plan.opts.slope)
    -- (the skin: of the body's radius, or for a body of none the length of its move)
    local tol = 10 * (pre.skin + 1e-9 * (abs(ax) + abs(ay))) + 1e-9 * self.span
    local bt, walk, clean, ground = huge, true, true, nil
    for _, b in ipairs(pre.bodies) do
      local e = self:E(b)
      local resp = e and self:moveResponse(plan, e)
      if resp and resp ~= 'cross' then
        if S.triking(M, b) then clean = false end
        local h = S.weep(M, -ux * snap, -uy * snap, b)
        if h then
          local dot = h.nx * ux + h.ny * uy
          if h.t < bt - 1e-9 then
            bt, walk, ground = h.t, dot >= c + 1e-6, b
          elseif h.t <= bt + 1e-9 then
            walk = walk and dot >= c + 1e-6
          end
        end
      end
    end
    if clean and bt < huge and walk and bt * snap > tol then
      self:fail('%s: a move with snap %s that does not go up ended %s above walkable ground (%s); %s', what, snap,
        bt * snap, ground, colsDesc())
    end
    if clean and bt < huge and walk then self:count('snapped moves checked') end
  end
end

---------------------------------------------------------------------------------------
-- Script actions

-- A nested query (any kind) with its own filter, checked against the model on the spot.
ACTIONS.query = function(self, s, ctx)
  local kinds = {}
  for _, k in ipairs({ 'check', 'queryPoint', 'queryRect', 'queryShape', 'rayCast', 'rayCastAll', 'cast', 'bodies',
    'move' }) do
    if not (self.F.queries and self.F.queries[k] == false) then kinds[#kinds + 1] = k end
  end
  local kind = kinds[self.rng:int(1, #kinds)]
  self:log('%s: a nested %s', s.tag, kind)
  self:count('nested ' .. kind)
  if kind == 'move' then
    local M = self:pickTarget(ctx)
    if not M then return end
    local plan = self:planMove(M)
    return Q.move(self, nil, nil, nil, plan)
  end
  return Q[kind](self)
end

ACTIONS.collisions = function(self, s)
  self:log('%s: collisions()', s.tag)
  return Q.collisions(self)
end

ACTIONS.spaceMove = function(self, s, ctx)
  local M = self:pickTarget(ctx)
  if not M then return end
  self:log('%s: space:move of another body', s.tag)
  local plan = self:planMove(M)
  return Q.move(self, nil, nil, nil, plan)
end

ACTIONS.remove = function(self, s, ctx)
  local b = self:pickTarget(ctx)
  if not b then return end
  self:log('%s: remove %s', s.tag, b)
  self:removeBody(b)
end

ACTIONS.add = function(self, s)
  local w, rng = self.w, self.rng
  local body
  if #w.pool > 0 and rng:next() < 0.3 then body = w.pool[rng:int(1, #w.pool)] else body = w:newBody() end
  local opts = rng:next() < 0.6 and w:randomOpts() or nil
  self:log('%s: add', s.tag)
  self:addBody(body, opts)
end

ACTIONS.transform = function(self, s, ctx)
  local b = self:pickTarget(ctx)
  if not b then return end
  local ch = self:geometryChange(b)
  self:log('%s: %s %s', s.tag, ch.desc, b)
  ch.apply(b)
  self:effect('moved', b)
  if ch.what == 'transform' then self:effect('transformed', b) end
  if ch.what == 'memberAdd' or ch.what == 'memberRemove' then self:effect('members', b) end
end

-- Move the body that the move or cast this filter serves is moving (a transform of it as a
-- whole): docs/space.md says that is an error, raised from that call (see subjectMoved).
ACTIONS.moveSubject = function(self, s)
  local b = s.subject
  if not b then return end
  local apply, desc = self:transformOp(b)
  self:log('%s: %s the body being moved, %s', s.tag, desc, b)
  apply(b)
  self:effect('moved', b)
  self:effect('transformed', b)
  local root = self.rootOf[b]
  if root then self:effect('moved', root) end
end

ACTIONS.member = function(self, s, ctx)
  local b = self:pickTarget(ctx)
  if not b or not MUTABLE[self.w.info[b].kind] then return end
  local ch = self:geometryChange(b)
  self:log('%s: %s %s', s.tag, ch.desc, b)
  ch.apply(b)
  self:effect('moved', b)
  if ch.what == 'memberAdd' or ch.what == 'memberRemove' then self:effect('members', b) end
end

ACTIONS.set = function(self, s, ctx)
  local b = self:pickTarget(ctx)
  if not b then return end
  self:log('%s: set', s.tag)
  self:setBody(b, self.w:randomOpts())
end

ACTIONS.setFilter = function(self, s)
  self:log('%s: setFilter', s.tag)
  if self.rng:next() < 0.3 then
    self:setPairFilter(nil)
  else
    self:setPairFilter(self:newScript('pair'))
  end
end

ACTIONS.on = function(self, s)
  local events = { 'begin', 'stay', 'end' }
  local E = events[self.rng:int(1, 3)]
  self:log('%s: on', s.tag)
  self:on(E, self:newScript('event'))
end

ACTIONS.off = function(self, s, ctx)
  local rng = self.rng
  local reg
  if ctx.reg and not ctx.reg.off and rng:next() < 0.4 then
    reg = ctx.reg -- itself
  elseif ctx.reg and rng:next() < 0.6 then -- a later callback of the same event
    local list, later = self.cbs[ctx.reg.event], {}
    local after = false
    for _, r in ipairs(list) do
      if after then later[#later + 1] = r end
      if r == ctx.reg then after = true end
    end
    if #later > 0 then reg = later[rng:int(1, #later)] end
  end
  if not reg then
    local all = {}
    for _, E in ipairs({ 'begin', 'stay', 'end' }) do
      for _, r in ipairs(self.cbs[E]) do
        if r.script then all[#all + 1] = r end
      end
    end
    if #all == 0 then return end
    reg = all[rng:int(1, #all)]
  end
  self:log('%s: off', s.tag)
  self:off(reg)
end

ACTIONS.raise = function(self, s)
  self.nboom = self.nboom + 1
  self:log('%s: raise boom #%d', s.tag, self.nboom)
  error(setmetatable({ n = self.nboom }, Boom), 0)
end

-- A call with bad arguments, caught: it must raise, and change nothing.
ACTIONS.badCall = function(self, s, ctx)
  local sp, rng = self.space, self.rng
  local b = self:pickTarget(ctx)
  local E = self.w.entries
  local any = b or (E[1] and E[1].body)
  local calls = {
    function() return 'move with slope -1', pcall(sp.move, sp, b, 0, 0, nil, { slope = -1 }) end,
    function() return 'move with up {0, 0}', pcall(sp.move, sp, b, 0, 0, nil, { up = { 0, 0 } }) end,
    function() return 'move to NaN', pcall(sp.move, sp, b, 0 / 0, 0) end,
    function() return 'move with an unknown option', pcall(sp.move, sp, b, 0, 0, nil, { speed = 1 }) end,
    function() return 'cast by NaN', pcall(sp.cast, sp, any, 0 / 0, 1) end,
    function() return 'queryRect of width -1', pcall(sp.queryRect, sp, 0, 0, -1, 1) end,
    function() return 'rayCast along (0, 0)', pcall(sp.rayCast, sp, 0, 0, 0, 0) end,
    function() return 'check with a bad filter', pcall(sp.check, sp, any, 'filter') end,
    function() return 'set layer 5', pcall(sp.set, sp, any, { layer = 5 }) end,
    function() return 'add twice', pcall(sp.add, sp, any) end,
    function() return "on('bogus')", pcall(sp.on, sp, 'bogus', print) end,
    function() return 'setFilter(5)', pcall(sp.setFilter, sp, 5) end,
  }
  if not any then return end
  local i = rng:int(b and 1 or 5, #calls)
  if b and ctx.kind == 'move' and rng:next() < 0.7 then i = rng:int(1, 2) end -- (the outer move keeps its options?)
  local desc, ok, e = calls[i]()
  self:log('%s: bad call: %s', s.tag, desc)
  if not ok and (isFailure(e) or isBoom(e)) then error(e, 0) end
  self:check(not ok, '%s: %s did not raise an error', s.tag, desc)
  self:check(type(e) == 'string', '%s: %s raised %s, not a message', s.tag, desc, e)
end

-- A nested query whose filter raises on its first call, caught by the script.
ACTIONS.caught = function(self, s)
  local kinds = { 'check', 'queryPoint', 'queryRect', 'queryShape', 'rayCastAll' }
  if self.F.levelsLetGo then kinds[#kinds + 1], kinds[#kinds + 2] = 'rayCast', 'cast' end
  local kind = kinds[self.rng:int(1, #kinds)]
  self:log('%s: a nested %s whose filter raises, caught', s.tag, kind)
  local saved = self.queryFilter
  self.queryFilter = function(p)
    p.queryFilter = nil
    local sc = p:newScript('query', true)
    sc.actions = { { op = 'raise', at = 1 } }
    return { filter = p:queryFilterFn(sc), script = sc, pass = function(e) return p:queryPass(sc, e.body) end,
      desc = p:describeScript(sc) }
  end
  local ok, e = pcall(Q[kind], self)
  self.queryFilter = saved
  if not ok then
    if not isBoom(e) then error(e, 0) end
    self:log('%s: caught %s', s.tag, tostring(e))
    self:count('errors caught by a script')
  end
end

---------------------------------------------------------------------------------------
-- Top-level changes

local CHANGES = {}
WM.CHANGES = { 'add', 'remove', 'set', 'transform', 'member', 'touch', 'setFilter', 'on', 'off', 'addResponse' }

-- Each returns the body changed and the point to aim the next query at, or nil; `plan`
-- (optional) is the state a move right after it needs: its copy of the changed body.
function CHANGES.add(self)
  local w, rng = self.w, self.rng
  local body
  local r = rng:next()
  local E = w.entries
  if r < 0.25 and #w.pool > 0 then
    body = w.pool[rng:int(1, #w.pool)]
  elseif r < 0.35 and #E > 0 then
    local src = E[rng:int(1, #E)].body
    body = src:copy()
    local inf = w.info[src]
    w:register(body, inf.kind, inf.exact)
  else
    body = w:newBody()
  end
  local x, y = body:getCentroid()
  local opts = rng:next() < 0.6 and w:randomOpts() or nil
  return body, { x, y }, function() self:addBody(body, opts) end
end

function CHANGES.remove(self)
  local E = self.w.entries
  if #E == 0 then return nil end
  local body = E[self.rng:int(1, #E)].body
  local x, y = body:getCentroid()
  return body, { x, y }, function() self:removeBody(body) end
end

function CHANGES.set(self)
  local E = self.w.entries
  if #E == 0 then return nil end
  local body = E[self.rng:int(1, #E)].body
  local x, y = body:getCentroid()
  local opts = self.w:randomOpts()
  return body, { x, y }, function() self:setBody(body, opts) end
end

function CHANGES.transform(self)
  local E = self.w.entries
  if #E == 0 then return nil end
  local body = E[self.rng:int(1, #E)].body
  local ch = self:geometryChange(body)
  return body, { ch.tx, ch.ty }, function()
    self:log('%s %s', ch.desc, body)
    ch.apply(body)
    self:effect('moved', body)
  end, ch.apply
end

function CHANGES.member(self)
  local list = {}
  for _, e in ipairs(self.w.entries) do
    if MUTABLE[self.w.info[e.body].kind] then list[#list + 1] = e.body end
  end
  if #list == 0 then return nil end
  local body = list[self.rng:int(1, #list)]
  local ch
  for _ = 1, 3 do
    ch = self:geometryChange(body)
    if ch.what ~= 'transform' then break end
  end
  return body, { ch.tx, ch.ty }, function()
    self:log('%s %s', ch.desc, body)
    ch.apply(body)
    self:effect('moved', body)
  end, ch.apply
end

-- An exact body placed exactly against another (touching is not colliding).
function CHANGES.touch(self)
  local list = {}
  for _, e in ipairs(self.w.entries) do
    if self.w.info[e.body].exact then list[#list + 1] = e.body end
  end
  if #list < 2 then
    local w = self.w
    local body = w:register(S.hapes.Rectangle(w:snap(w.cx), w:snap(w.cy), 4 * w.u, 6 * w.u), 'shape', true)
    return body, { w.cx, w.cy }, function() self:addBody(body, nil) end
  end
  local i = self.rng:int(1, #list)
  local j = self.rng:int(1, #list - 1)
  if j >= i then j = j + 1 end
  local a, b = list[i], list[j]
  local dx, dy = self:touchDelta(a, b)
  local x, y = b:getCentroid()
  local apply = function(o) o:translate(dx, dy) end
  return b, { x + dx, y + dy }, function()
    self:log('touch %s against %s: translate (%s, %s)', b, a, dx, dy)
    apply(b)
    self:effect('moved', b)
    self.w.info[b].exact = true -- (a translation on the exact grid)
  end, apply
end

function CHANGES.setFilter(self)
  local s
  if not (self.pf and self.rng:next() < 0.3) then s = self:newScript('pair') end
  return nil, nil, function() self:setPairFilter(s) end
end

function CHANGES.on(self)
  if not self.events then return nil end
  local E = ({ 'begin', 'stay', 'end' })[self.rng:int(1, 3)]
  local s = self:newScript('event')
  return nil, nil, function() self:on(E, s) end
end

function CHANGES.off(self)
  if not self.events then return nil end
  local all = {}
  for _, E in ipairs({ 'begin', 'stay', 'end' }) do
    for _, r in ipairs(self.cbs[E]) do
      if r.script then all[#all + 1] = r end
    end
  end
  if #all == 0 then return nil end
  local reg = all[self.rng:int(1, #all)]
  return nil, nil, function() self:off(reg) end
end

function CHANGES.addResponse(self)
  if not self.F.responses then return nil end
  local name = self.rng:next() < 0.5 and 'stopper' or 'passer'
  local s = self:newScript('response')
  return nil, nil, function() self:addResponse(name, s) end
end

-- A response of the game's: 'stopper' stops at the touch, 'passer' goes on to the goal.
function P:addResponse(name, s)
  local old = self.responses[name]
  if old then self.deadFns[old.fn] = 'the response ' .. old.tag end
  s.fn = function(space, col, x, y, gx, gy)
    self:check(space == self.space, '%s: the response got %s, not the space', s.tag, space)
    self:check(type(col) == 'table' and col.type == name, '%s: the response %s got a collision of type %s', s.tag, name,
      type(col) == 'table' and col.type)
    self:check(type(x) == 'number' and type(y) == 'number' and type(gx) == 'number' and type(gy) == 'number',
      '%s: the response got %s, %s, %s, %s', s.tag, x, y, gx, gy)
    self:runScript(s, { kind = 'response', args = { col.other } })
    if name == 'stopper' then return col.touchX, col.touchY, col.touchX, col.touchY end
    return col.touchX, col.touchY, gx, gy
  end
  self.responses[name] = s
  self.space:addResponse(name, s.fn)
  self:log('addResponse(%s, %s)', name, self:describeScript(s))
end

---------------------------------------------------------------------------------------
-- The program

local CHANGE_WEIGHTS = { transform = 4, member = 1.5, add = 2, remove = 1.5, set = 1.5, touch = 1, setFilter = 0.5,
  on = 0.7, off = 0.5, addResponse = 0.2 }
local LEAN_CHANGE_WEIGHTS = {} -- (leaning toward moves: addResponse more often)
for k, v in pairs(CHANGE_WEIGHTS) do LEAN_CHANGE_WEIGHTS[k] = v end
LEAN_CHANGE_WEIGHTS.addResponse = 0.8
local QUERY_WEIGHTS = { collisions = 3, check = 2, queryPoint = 1.5, queryRect = 1.5, queryShape = 1.5, rayCast = 2,
  rayCastAll = 1.5, cast = 2, move = 4, bodies = 0.8 }

local function weighted(rng, names, weights, F)
  local total, acc = 0, {}
  for _, n in ipairs(names) do
    local wgt = (F == nil or F[n] ~= false) and weights[n] or 0
    total = total + wgt
    acc[#acc + 1] = total
  end
  local r = rng:next() * total
  for i, n in ipairs(names) do
    if r < acc[i] then return n end
  end
  return names[#names]
end

function P:change(name)
  local body, target, run, apply = CHANGES[name](self)
  if not run then return false end
  self:count('op ' .. name)
  return true, body, target, run, apply
end

-- One step: a change, a query, or (often) a change and at once a query aimed at it.
function P:step()
  local rng, F = self.rng, self.F
  local r = rng:next()
  if r < 0.45 and F.pairs then
    -- a change, then a query with nothing in between
    local name = weighted(rng, { 'transform', 'member', 'add', 'remove', 'set', 'touch' }, CHANGE_WEIGHTS, F.changes)
    local ok, X, target, run, apply = self:change(name)
    if not ok then return end
    local q = weighted(rng, WM.QUERIES, QUERY_WEIGHTS, F.queries)
    self:count('op ' .. q)
    self:count('change then query')
    local sub
    if q == 'move' and apply and X then -- the move's start state reads a copy changed the same way
      sub = { [X] = X:copy() }
    end
    self:top(run)
    if sub then apply(sub[X]) end
    self.stepNo = self.stepNo + 1
    self:top(function() Q[q](self, target, X, sub) end)
  elseif r < 0.72 then
    local name = weighted(rng, WM.CHANGES, self.lean.moves and LEAN_CHANGE_WEIGHTS or CHANGE_WEIGHTS, F.changes)
    local ok, _, _, run = self:change(name)
    if ok then self:top(run) end
  else
    local q = weighted(rng, WM.QUERIES, QUERY_WEIGHTS, F.queries)
    self:count('op ' .. q)
    self:top(function() Q[q](self) end)
  end
end

--- Run the program: populate, then `steps` steps, then the end checks.
function P:run(steps)
  local rng, w, F = self.rng, self.w, self.F
  self.events = F.events and (self.lean.events or rng:next() < 0.85)
  if self.events then
    for _, E in ipairs({ 'begin', 'stay', 'end' }) do
      local reg = { event = E, fn = self:recorderFn(E), tag = 'recorder:' .. E }
      self.cbs[E][1] = reg
      self.space:on(E, reg.fn)
    end
    if self.lean.events then
      -- (a callback that raises, then one or two more on the same event)
      local E = ({ 'begin', 'stay', 'stay', 'end' })[rng:int(1, 4)]
      local s = self:newScript('event')
      self:leanAction(s, { 'raise' })
      self:on(E, s)
      for _ = 1, rng:int(1, 2) do self:on(E, self:newScript('event')) end
    end
    for _ = 1, rng:int(0, 5) do
      local E = ({ 'begin', 'stay', 'end' })[rng:int(1, 3)]
      self:on(E, self:newScript('event'))
    end
  end
  if F.responses then
    self:addResponse('stopper', self:newScript('response'))
    self:addResponse('passer', self:newScript('response'))
  end
  if self.lean.pair then -- (a pair filter from the start, which raises, removes or calls collisions())
    local s = self:newScript('pair')
    self:leanAction(s, LEAN_ACTIONS.pair)
    self:setPairFilter(s)
  elseif rng:next() < 0.4 then
    self:setPairFilter(self:newScript('pair'))
  end
  local n0 = 5 + floor(35 * rng:next() ^ 2)
  for _ = 1, n0 do self:addBody(w:newBody(), rng:next() < 0.6 and w:randomOpts() or nil) end
  if self.lean.moves then self:addWalker() end
  if F.crowd and self.index % 10 == 0 then self:crowd() end
  self:count('programs')
  self:count('bodies at the start', n0)
  while self.stepNo < steps do
    self.stepNo = self.stepNo + 1
    self:step()
  end
  self:count('steps', self.stepNo)
  if F.gc then self:gcCheck() end
end

-- The moves lean: a floor below the bodies and a walker on it; a quarter of the moves are
-- walks along it with snap and a slope (the snap check needs ground below the end of a move
-- that does not go up). Both are bodies as any other: the program may move or remove them.
function P:addWalker()
  local w = self.w
  local L, h, r = w:side(), w:snap(w.s), w.s * 0.4
  local top = w:snap(w.cy + L)
  local ground = w:register(S.hapes.Rectangle(w:snap(w.cx), top + h / 2, w:snap(2 * L), h), 'shape', true)
  self:addBody(ground, nil)
  local walker = w:register(S.hapes.Circle(w.cx, top - r * 1.05, r), 'shape')
  self:addBody(walker, nil)
  self.walk = setmetatable({ ground = ground, walker = walker }, { __mode = 'v' }) -- (the model keeps no body alive)
end

-- A walk of the walker (see addWalker): along the ground to a point above it, or nil when
-- the walker is not in the space or is being moved.
function P:walkPlan()
  local walk, rng = self.walk, self.rng
  local M, ground = walk and walk.walker, walk and walk.ground
  if not (M and ground and self:E(M) and self:E(ground)) or self.moving[M] then return nil end
  local _, y = M:getCentroid()
  local x0, _, x1 = ground:getBounds()
  local plan = { M = M, fc = {}, pfc = {}, gx = rng:range(x0, x1), gy = y,
    opts = { snap = self.w.s * logRange(rng, 0.1, 1), slope = rng:range(0.5, 1.3) } }
  if rng:next() < 0.3 then
    plan.script = self:newScript('move', false, M)
    plan.filter = self:moveFilterFn(plan.script, plan)
  end
  return plan
end

-- A row of coins and a bullet through them with a filter that crosses everything; then the
-- coins go (they would make every later step slow).
function P:crowd()
  local w, rng = self.w, self.rng
  local n = rng:int(66, 90)
  local s = w.s * 0.2
  local x0, y = w.cx - n * s, w.cy + 3 * w:side()
  local pf = self.pf -- (no pair filter while the bullet flies: every coin counts)
  if pf then self:setPairFilter(nil) end
  local coins = {}
  for i = 1, n do
    coins[i] = self:addBody(w:register(S.hapes.Circle(x0 + 2 * s * i, y, s * 0.6), 'shape'), nil).body
  end
  local bullet = w:register(S.hapes.Circle(x0 - 2 * s, y, s * 0.3), 'shape')
  self:addBody(bullet, nil)
  local sc = self:newScript('move', true)
  sc.crossAll = true
  local plan = { M = bullet, fc = {}, pfc = {}, gx = x0 + 2 * s * (n + 2), gy = y, script = sc }
  plan.filter = self:moveFilterFn(sc, plan)
  self.stepNo = self.stepNo + 1
  self:count('crowd moves') -- (not an 'op move': those are the random ones)
  self:top(function() Q.move(self, nil, nil, nil, plan) end)
  self:top(function()
    for _, c in ipairs(coins) do self:removeBody(c) end
    if pf then self:setPairFilter(pf) end
  end)
end

-- A path of fields from root to target (breadth first), for a failure message: who keeps it
-- alive. Weak tables are not paths; `barrier` is not entered (the program itself); `skip`
-- maps a table to true (its integer keys are not followed) or to a set of the names not
-- followed; `tablesOnly`: no metatables, no upvalues.
local function pathTo(root, target, skip, barrier, tablesOnly)
  -- (nor the globals: a path through them is not the space's)
  local seen, queue, head = { [root] = true, [barrier] = true, [_G] = true, [package] = true,
    [package.loaded] = true }, { { root, 'space' } }, 1
  while queue[head] do
    local node, path = queue[head][1], queue[head][2]
    head = head + 1
    local function visit(v, name)
      if v == target then return path .. name end
      if (type(v) == 'table' or type(v) == 'function' and not tablesOnly) and not seen[v] then
        seen[v] = true
        queue[#queue + 1] = { v, path .. name }
      end
    end
    if type(node) == 'table' then
      local mt = getmetatable(node)
      local mode = mt and rawget(mt, '__mode')
      if not mode then
        local sk = skip and skip[node]
        -- (in a fixed order: the same path on every VM)
        local keys = {}
        for k in pairs(node) do
          if type(k) == 'string' and not (sk and sk ~= true and sk[k]) or type(k) == 'number' and sk ~= true then
            keys[#keys + 1] = k
          end
        end
        table.sort(keys, function(x, y)
          if type(x) ~= type(y) then return type(x) == 'number' end
          return x < y
        end)
        for _, k in ipairs(keys) do
          local r = visit(node[k], '.' .. tostring(k))
          if r then return r end
        end
        for k, v in pairs(node) do -- (table keys: weak tables aside, none in strike's state)
          if type(k) ~= 'string' and type(k) ~= 'number' then
            local r = visit(v, '[a key]') or visit(k, '[key]')
            if r then return r end
          end
        end
      end
      if mt and not tablesOnly then
        local r = visit(mt, '<metatable>')
        if r then return r end
      end
    elseif not tablesOnly then
      for i = 1, 200 do
        local name, v = debug.getupvalue(node, i)
        if not name then break end
        local r = visit(v, '<upvalue ' .. name .. '>')
        if r then return r end
      end
    end
  end
  return nil
end

-- The end: every callback off, no pair filter, one collisions() (every pair of a removed
-- body ends), a move and each query once (their scratch renewed), the out tables emptied;
-- then no body the model forgot, and no function it let go, may be alive.
function P:gcCheck()
  self.stepNo = self.stepNo + 1
  self:log('the end: off, setFilter(nil), collisions(), a move, each query')
  self:top(function()
    for _, E in ipairs({ 'begin', 'stay', 'end' }) do
      local list = self.cbs[E]
      for i = #list, 1, -1 do
        if list[i].script then self:off(list[i]) end
      end
    end
    if self.pf then self:setPairFilter(nil) end
  end)
  self:top(function() Q.collisions(self) end)
  for _, E in ipairs({ 'begin', 'stay', 'end' }) do
    local list = self.cbs[E]
    if list[1] then self.space:off(E, list[1].fn) end
    self.cbs[E] = {}
  end
  self.open = {}
  self.outs = {}
  self.kept = nil
  local sp = self.space
  -- (far from every body, within the range of motion: limits.REACH sizes of the probe)
  local far = 1e6
  local probe = S.hapes.Circle(far, far, 1)
  sp:add(probe)
  sp:move(probe, far, far)
  sp:move(probe, far + 1, far)
  sp:check(probe)
  sp:queryShape(probe)
  sp:queryPoint(far, far)
  sp:queryRect(far, far, 1, 1)
  sp:rayCast(far - 5, far, 1, 0)
  sp:rayCastAll(far - 5, far, 1, 0)
  sp:cast(probe, 1, 0)
  sp:collisions()
  sp:remove(probe)
  local a, b = S.hapes.Circle(0, 0, 1), S.hapes.Circle(0.5, 0, 1)
  S.triking(a, b)
  S.weep(a, 1, 0, b)
  for _ = 1, 2 do collectgarbage('collect') end
  -- What the space's own tables hold (README, "Conventions", Reused tables; docs/moving.md,
  -- "Moving bodies in a space": a move's list and its records are the space's, reused by the
  -- next move): the last collision list of each move level, space._cols[d][i], is a result
  -- still valid, and may name bodies removed since; nothing else of the space may keep a
  -- removed body or a dropped function alive. (The library's module scratch, reached only
  -- through upvalues of its functions, holds at most the last shapes it processed: it is not
  -- walked.)
  local skip = {}
  for _, list in pairs(rawget(sp, '_cols') or {}) do skip[list] = true end
  if not self.F.errorScratchLetsGo then -- (see FEATURES.errorScratchLetsGo)
    for _, level in pairs(rawget(sp, '_levels') or {}) do
      skip[level] = { hits = true, one1 = true, one2 = true }
      if type(level.stepHit) == 'table' then skip[level.stepHit] = { body = true } end
    end
    for _, list in pairs(rawget(sp, '_cols') or {}) do
      if type(list.hit) == 'table' then skip[list.hit] = { body = true } end
    end
  end
  if not self.F.contactShapesLetGo then -- (see FEATURES.contactShapesLetGo)
    for _, rec in pairs(rawget(sp, '_active') or {}) do
      if type(rec) == 'table' then
        skip[rec] = { _sa = true, _sb = true }
        if type(rec._c) == 'table' then skip[rec._c] = { _spares = true } end
      end
    end
  end
  local left, where = {}, {}
  for body, id in pairs(self.dropped) do
    self:check(not pathTo(self, body, nil, sp, true), 'internal: the model keeps #%d alive: %s', id,
      tostring(pathTo(self, body, nil, sp, true)))
    -- (a body alive but not reachable from the space at all is not the space's doing:
    -- LuaJIT's compiled traces may hold one as a constant)
    local path = pathTo(sp, body, skip, self, true)
    if path then
      left[#left + 1] = id
      where[id] = path
    end
  end
  table.sort(left)
  if #left > 0 then
    self:fail('the space keeps %d removed bodies alive (ids %s) after the program let them go; #%d: %s', #left,
      table.concat(left, ', '), left[1], where[left[1]])
  end
  local fns, path, whose = 0, nil, nil
  for fn, desc in pairs(self.deadFns) do
    local p = pathTo(sp, fn, skip, self, true)
    if p then
      fns = fns + 1
      if not path or p < path then path, whose = p, desc end
    end
  end
  self:check(fns == 0, 'the space keeps %d functions alive (filters, callbacks, responses) that it no longer uses'
    .. ' (%s): %s', fns, whose, path)
end

WM.Program = P
WM.ACTION_ORDER = ACTION_ORDER
return WM
