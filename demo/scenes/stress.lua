--- Scene 5, stress: hundreds of moving bodies of mixed shapes bouncing around the window.
--- Every body sits in an S.pace, which notices their moves by itself; each frame
--- `space:collisions(out)` gives the colliding pairs with their MTVs (one reused list), and
--- S.ettle pushes them apart; the bodies of those pairs are drawn yellow. The space's contact
--- events show too: a body flashes white when one of its contacts begins ('begin'), fading
--- back to its colour over M.FLASH_TIME (a contact here mostly lasts one frame, as S.ettle
--- separates the pair at once), and the status bar counts the contacts that began and ended
--- this frame. B shows the broadphase (S.howSpace: the tree's boxes).
local ROOT = (...):match('^(.-)scenes%.[^%.]+$')
local prng = require('spec.helpers.prng') -- the specs' seeded generator (main.lua puts the root on the path)
local layout = require(ROOT .. 'util.layout')
local scene = require(ROOT .. 'util.scene')

local M = {}

M.name = 'Stress'
M.help = {
  '+ / -: 50 bodies more / fewer   B: broadphase   R: reset',
  'Yellow: colliding    White, fading: a contact began',
}

M.COUNT = 300               -- bodies at start
M.SEED = 20240601
--- The scripted screenshot shows the state after this many updates of 1/60 s (see
--- util/scene.lua, advance): a busy frame, 11 pairs colliding (yellow; one of them already
--- at the frame before), bodies whose contacts began in the last M.FLASH_TIME (white, fading),
--- and the real counts in the status bar.
M.SHOT_FRAMES = 94
local MIN_COUNT, MAX_COUNT, STEP_COUNT = 50, 2000, 50
local RMIN, RMAX = 7, 11    -- body radii (px)
local SMIN, SMAX = 30, 110  -- speeds (px/s)
M.FLASH_TIME = 0.25         -- seconds a body's flash takes to fade after one of its contacts began

local KINDS = {
  { name = 'circle', rgb = { 150, 100, 190 } },
  { name = 'box', rgb = { 70, 120, 190 } },
  { name = 'triangle', rgb = { 190, 150, 60 } },
  { name = 'pentagon', rgb = { 60, 150, 120 } },
  { name = 'capsule', rgb = { 200, 110, 70 } },
}
local HOT = { 250, 232, 150 }
local FLASH = { 255, 255, 255 }
local OUTLINE = { 20, 22, 28 }
local BROADPHASE = { 235, 238, 245 } -- S.howSpace's bodies (its boxes have their own colour)

-- One body of a random kind, size, angle and velocity, centred on (x, y), added to the space.
local function spawn(state, x, y)
  local T, rng = state.S.trikers, state.rng
  local k = rng:int(1, #KINDS)
  local r, angle = rng:range(RMIN, RMAX), rng:range(0, 2 * math.pi)
  local body
  if k == 1 then
    body = T.Circle(x, y, r)
  elseif k == 2 then
    body = T.Rectangle(x, y, 1.6 * r, 1.1 * r, angle)
  elseif k == 3 then
    body = T.RegularPolygon(x, y, 3, r, angle)
  elseif k == 4 then
    body = T.RegularPolygon(x, y, 5, r, angle)
  else
    body = T.Capsule(x, y, 1.2 * r, 2 * r, angle)
  end
  local speed, heading = rng:range(SMIN, SMAX), rng:range(0, 2 * math.pi)
  local n = #state.bodies + 1
  local b = { body = body, kind = KINDS[k], vx = speed * math.cos(heading), vy = speed * math.sin(heading),
    hit = false, flash = 0, label = 'body ' .. n }
  state.bodies[n] = b
  state.byBody[body] = b
  state.space:add(body)
end

--- The initial state: M.COUNT bodies on a jittered grid, none overlapping, none moved yet.
---@param S table strike @param w number @param h number
---@return table state
function M.new(S, w, h)
  local fw, fh = layout.playfield(w, h)
  local stats = { bodies = 0, collisions = 0, begins = 0, ends = 0, ms = 0, msTotal = 0, frames = 0 }
  local byBody = {} -- the scene's record of each body in the space
  local space = S.pace()
  -- The contact events run during space:collisions(). (They use only tables that the R reset
  -- keeps: it copies a fresh state's fields into the state main.lua holds.)
  space:on('begin', function(a, b)
    stats.begins = stats.begins + 1
    byBody[a].flash, byBody[b].flash = M.FLASH_TIME, M.FLASH_TIME
  end)
  space:on('end', function() stats.ends = stats.ends + 1 end)
  local state = {
    S = S, w = w, h = h, fieldW = fw, fieldH = fh, rng = prng.new(M.SEED), bodies = {}, byBody = byBody,
    space = space, pairs = {}, showBroadphase = false, stats = stats,
  }
  -- one body per cell of a cols x rows lattice, jittered but kept inside its cell
  local cols = math.ceil(math.sqrt(M.COUNT * fw / fh))
  local rows = math.ceil(M.COUNT / cols)
  local cw, ch = fw / cols, fh / rows
  local jx, jy = math.max(0, cw / 2 - RMAX - 1), math.max(0, ch / 2 - RMAX - 1)
  for i = 0, M.COUNT - 1 do
    local col, row = i % cols, math.floor(i / cols)
    spawn(state, (col + 0.5) * cw + state.rng:range(-jx, jx), (row + 0.5) * ch + state.rng:range(-jy, jy))
  end
  stats.bodies = #state.bodies
  return state
end

-- Keep a body inside the field, bouncing off its sides.
local function bounce(state, b)
  local x0, y0, x1, y1 = b.body:getBounds()
  if x0 < 0 then b.body:translate(-x0, 0); b.vx = math.abs(b.vx)
  elseif x1 > state.fieldW then b.body:translate(state.fieldW - x1, 0); b.vx = -math.abs(b.vx) end
  if y0 < 0 then b.body:translate(0, -y0); b.vy = math.abs(b.vy)
  elseif y1 > state.fieldH then b.body:translate(0, state.fieldH - y1); b.vy = -math.abs(b.vy) end
end

--- The first half of an update: move every body by its velocity over dt seconds (the
--- space notices), bounce it off the field's sides and let its flash fade.
---@param state table @param dt number seconds
function M.move(state, dt)
  for _, b in ipairs(state.bodies) do
    b.body:translate(b.vx * dt, b.vy * dt)
    bounce(state, b)
    b.hit = false
    if b.flash > 0 then b.flash = math.max(0, b.flash - dt) end
  end
end

--- The second half: the colliding pairs from the space (its 'begin' and 'end' callbacks run
--- meanwhile), each resolved with its MTV; timed with state.clock, which demo/main.lua sets
--- to love.timer.getTime (os.clock elsewhere).
---@param state table
function M.collide(state)
  local S, stats, byBody = state.S, state.stats, state.byBody
  local clock = state.clock or os.clock
  local t0 = clock()
  stats.begins, stats.ends = 0, 0
  local out, n = state.space:collisions(state.pairs)
  for i = 1, n do
    local rec = out[i]
    local a, b, m = byBody[rec.a], byBody[rec.b], rec.mtv
    a.hit, b.hit = true, true
    S.ettle(m) -- half each: equal masses
    -- An elastic collision of equal masses swaps the velocities' components along the
    -- normal; only when they approach each other (else they are already parting).
    local nx, ny = m.nx, m.ny -- from a toward b
    local vrel = (b.vx - a.vx) * nx + (b.vy - a.vy) * ny
    if vrel < 0 then
      a.vx, a.vy = a.vx + vrel * nx, a.vy + vrel * ny
      b.vx, b.vy = b.vx - vrel * nx, b.vy - vrel * ny
    end
  end
  stats.collisions = n
  stats.ms = (clock() - t0) * 1000
  -- the mean since the start or the last change of count
  local bodies = state.bodies
  if stats.bodies ~= #bodies then stats.msTotal, stats.frames, stats.bodies = 0, 0, #bodies end
  stats.msTotal = stats.msTotal + stats.ms
  stats.frames = stats.frames + 1
end

--- Move every body, then find and resolve the collisions.
---@param state table @param dt number seconds
function M.update(state, dt)
  M.move(state, dt)
  M.collide(state)
end

---@param state table @param key string
function M.keypressed(state, key)
  local n = #state.bodies
  if key == '+' or key == '=' or key == 'kp+' then
    for _ = 1, math.min(STEP_COUNT, MAX_COUNT - n) do
      spawn(state, state.rng:range(RMAX, state.fieldW - RMAX), state.rng:range(RMAX, state.fieldH - RMAX))
    end
  elseif key == '-' or key == 'kp-' then
    -- (their contacts end at the next collisions(): the 'end' events count them then)
    for i = n, math.max(MIN_COUNT, n - STEP_COUNT) + 1, -1 do
      local body = state.bodies[i].body
      state.space:remove(body)
      state.byBody[body], state.bodies[i] = nil, nil
    end
  elseif key == 'b' then
    state.showBroadphase = not state.showBroadphase
  elseif key == 'r' then
    scene.reset(M, state)
  end
end

--- Lines for the status bar: the counts of the last update and its collision time.
---@param state table
---@return string[]
function M.status(state)
  local s = state.stats
  return {
    ('%d bodies in an S.pace: %d colliding pairs; contacts this frame: %d began, %d ended'):format(s.bodies,
      s.collisions, s.begins, s.ends),
    ('collision time: %.2f ms this frame, %.2f ms/frame on average over %d frames'):format(s.ms,
      s.frames > 0 and s.msTotal / s.frames or 0, s.frames),
  }
end

-- A body's fill: yellow while colliding; else its kind's colour, mixed with white by what
-- is left of its flash (whole 0-255 values: the probes compare them exactly).
local function fillColour(b)
  if b.hit then return HOT end
  local rgb = b.kind.rgb
  if b.flash <= 0 then return rgb end
  local t = b.flash / M.FLASH_TIME
  local mixed = {}
  for i = 1, 3 do mixed[i] = math.floor(rgb[i] + (FLASH[i] - rgb[i]) * t + 0.5) end
  return mixed
end

--- Draw with a painter (util/lovepaint.lua on screen, util/probe.lua for the probes); with
--- B, the space as S.howSpace draws it on top.
---@param state table @param P table
function M.paint(state, P)
  for _, b in ipairs(state.bodies) do
    P:fill(b.body, fillColour(b), b.label)
    P:outline(b.body, OUTLINE)
  end
  if state.showBroadphase then P:space(state.space, BROADPHASE) end
end

--- Draw on screen (LÖVE only).
function M.draw(state) scene.draw(M, state) end

--- Screenshot probes of this state: eight bodies clear of the overlays and big enough for a
--- probe, taken in turn from those colliding, those flashing and the others (each group in
--- order of creation), and background.
---@param state table
---@return table[]
function M.probes(state)
  local reserved = layout.reserved(M, state.w, state.h)
  local groups = { {}, {}, {} }
  for _, b in ipairs(state.bodies) do
    local x0, y0, x1, y1 = b.body:getBounds()
    local clear = true
    for _, r in ipairs(reserved) do
      if x1 > r[1] - 10 and x0 < r[1] + r[3] + 10 and y1 > r[2] - 10 and y0 < r[2] + r[4] + 10 then clear = false end
    end
    if clear then
      local g = groups[b.hit and 1 or b.flash > 0 and 2 or 3]
      g[#g + 1] = b.label
    end
  end
  local labels = {}
  for i = 1, #state.bodies do
    for _, g in ipairs(groups) do labels[#labels + 1] = g[i] end
  end
  return scene.probes(M, state, labels, 8)
end

return M
