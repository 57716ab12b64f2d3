--- Scene 5, stress: hundreds of moving bodies of mixed shapes bouncing around the window.
--- A uniform grid (util/grid.lua) finds the pairs that share a cell; S.aabb discards those
--- whose boxes do not overlap; S.triking tests the rest and S.ettle pushes colliding
--- bodies apart. The status bar counts each stage and times the whole collision work.
local ROOT = (...):match('^(.-)scenes%.[^%.]+$')
local prng = require('spec.helpers.prng') -- the specs' seeded generator (main.lua puts the root on the path)
local layout = require(ROOT .. 'util.layout')
local scene = require(ROOT .. 'util.scene')
local Grid = require(ROOT .. 'util.grid')

local M = {}

M.name = 'Stress'
M.help = {
  '+ / -: 50 bodies more / fewer    R: reset',
  'Bright bodies are colliding this frame',
}

M.COUNT = 300               -- bodies at start
M.SEED = 20240601
local MIN_COUNT, MAX_COUNT, STEP_COUNT = 50, 2000, 50
local CELL = 32             -- grid cell (px): about the largest body's diameter
local RMIN, RMAX = 7, 11    -- body radii (px)
local SMIN, SMAX = 30, 110  -- speeds (px/s)

local KINDS = {
  { name = 'circle', rgb = { 150, 100, 190 } },
  { name = 'box', rgb = { 70, 120, 190 } },
  { name = 'triangle', rgb = { 190, 150, 60 } },
  { name = 'pentagon', rgb = { 60, 150, 120 } },
  { name = 'capsule', rgb = { 200, 110, 70 } },
}
local HOT = { 250, 232, 150 }
local OUTLINE = { 20, 22, 28 }

-- One body of a random kind, size, angle and velocity, centred on (x, y).
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
  state.bodies[n] = { body = body, kind = KINDS[k], vx = speed * math.cos(heading), vy = speed * math.sin(heading),
    hit = false, label = 'body ' .. n }
end

--- The initial state: M.COUNT bodies on a jittered grid, none overlapping, none moved yet.
---@param S table strike @param w number @param h number
---@return table state
function M.new(S, w, h)
  local fw, fh = layout.playfield(w, h)
  local state = {
    S = S, w = w, h = h, fieldW = fw, fieldH = fh, rng = prng.new(M.SEED), bodies = {},
    grid = Grid.new(CELL, fw, fh), mtv = S.MTV(),
    stats = { bodies = 0, candidates = 0, narrow = 0, collisions = 0, ms = 0, msTotal = 0, frames = 0 },
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
  state.stats.bodies = #state.bodies
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

-- The narrow phase for one candidate pair from the grid.
local function testPair(i, j, state)
  local S, stats = state.S, state.stats
  local a, b = state.bodies[i], state.bodies[j]
  if not S.aabb(a.body, b.body) then return end
  stats.narrow = stats.narrow + 1
  local m = S.triking(a.body, b.body, state.mtv)
  if not m then return end
  stats.collisions = stats.collisions + 1
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

--- Move every body, then find and resolve the collisions (timed with state.clock, which
--- demo/main.lua sets to love.timer.getTime; os.clock elsewhere).
---@param state table @param dt number seconds
function M.update(state, dt)
  local bodies, stats = state.bodies, state.stats
  for _, b in ipairs(bodies) do
    b.body:translate(b.vx * dt, b.vy * dt)
    bounce(state, b)
    b.hit = false
  end
  local clock = state.clock or os.clock
  local t0 = clock()
  local grid = state.grid
  grid:clear()
  for i, b in ipairs(bodies) do grid:insert(i, b.body:getBounds()) end
  stats.narrow, stats.collisions = 0, 0
  stats.candidates = grid:eachPair(testPair, state)
  stats.ms = (clock() - t0) * 1000
  -- the mean since the start or the last change of count
  if stats.bodies ~= #bodies then stats.msTotal, stats.frames, stats.bodies = 0, 0, #bodies end
  stats.msTotal = stats.msTotal + stats.ms
  stats.frames = stats.frames + 1
end

---@param state table @param key string
function M.keypressed(state, key)
  local n = #state.bodies
  if key == '+' or key == '=' or key == 'kp+' then
    for _ = 1, math.min(STEP_COUNT, MAX_COUNT - n) do
      spawn(state, state.rng:range(RMAX, state.fieldW - RMAX), state.rng:range(RMAX, state.fieldH - RMAX))
    end
  elseif key == '-' or key == 'kp-' then
    for i = n, math.max(MIN_COUNT, n - STEP_COUNT) + 1, -1 do state.bodies[i] = nil end
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
    ('%d bodies: %d grid pairs, %d narrow-phase tests (S.triking), %d collisions'):format(s.bodies, s.candidates,
      s.narrow, s.collisions),
    ('collision time: %.2f ms this frame, %.2f ms/frame on average over %d frames'):format(s.ms,
      s.frames > 0 and s.msTotal / s.frames or 0, s.frames),
  }
end

--- Draw with a painter (util/lovepaint.lua on screen, util/probe.lua for the probes).
---@param state table @param P table
function M.paint(state, P)
  for _, b in ipairs(state.bodies) do
    P:fill(b.body, b.hit and HOT or b.kind.rgb, b.label)
    P:outline(b.body, OUTLINE)
  end
end

--- Draw on screen (LÖVE only).
function M.draw(state) scene.draw(M, state) end

--- Screenshot probes of this state: eight bodies clear of the overlays and big enough
--- for a probe (in order of creation), and background.
---@param state table
---@return table[]
function M.probes(state)
  local reserved = layout.reserved(M, state.w, state.h)
  local labels = {}
  for _, b in ipairs(state.bodies) do
    local x0, y0, x1, y1 = b.body:getBounds()
    local clear = true
    for _, r in ipairs(reserved) do
      if x1 > r[1] - 10 and x0 < r[1] + r[3] + 10 and y1 > r[2] - 10 and y0 < r[2] + r[4] + 10 then clear = false end
    end
    if clear then labels[#labels + 1] = b.label end
  end
  return scene.probes(M, state, labels, 8)
end

return M
