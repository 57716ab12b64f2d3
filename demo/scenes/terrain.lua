--- Scene 4, terrain: a box and a ball walking and jumping over a floor of tiles (a row of
--- S.hapes.Rectangle in one compound collider) and a hilly S.trikers.Chain. Simple
--- kinematic physics: velocities, gravity, and every overlap resolved with S.triking and a
--- translation (S.hove, or a vertical push on ground), the MTV normal shown as an arrow.
local ROOT = (...):match('^(.-)scenes%.[^%.]+$')
local layout = require(ROOT .. 'util.layout')
local scene = require(ROOT .. 'util.scene')

local M = {}

M.name = 'Terrain'
M.help = {
  'Arrows: move the box, Up: jump',
  'A / D: move the ball, W: jump',
  'N: normals on/off    R: reset',
}

M.STEP = 1 / 120          -- fixed physics step (s): the same motion at any frame rate
local GRAVITY = 1400      -- px/s^2, down
local SPEED = 220         -- px/s, walking
local ACCEL = 2000        -- px/s^2, toward the walking speed while a key is held
local BRAKE = 700         -- px/s^2, toward rest otherwise (less: a body can be pushed)
local JUMP = 560          -- px/s, up
-- A contact whose normal points up at least this much is ground: the body stands on it.
-- (-ny > 0.6: slopes up to about 53 degrees.)
local GROUND_NY = 0.6
local MAX_PUSHES = 4      -- resolution passes per step
local SNAP = 3            -- px: how far down a walking body looks for the ground

local TILE = 40
local FLOOR_Y = 480       -- top of the tiles
local TILES = { { 120, 104, 92 }, { 100, 88, 78 } }
local TILE_EDGE = { 60, 52, 46 }
local GROUND = { 86, 74, 62 }
local GRASS = { 120, 190, 90 }
local BOX = { 70, 120, 190 }
local BALL = { 200, 110, 70 }
local OUTLINE = { 215, 220, 230 }
local NORMAL = { 255, 220, 60 }

-- The chain's points, left to right (so it is solid below and free above on screen).
local HILLS = { 400, 480, 470, 480, 530, 440, 580, 425, 630, 450, 670, 470, 730, 415, 800, 415 }

-- The deepest MTV between the terrain and a body, or nil (S.triking picks the deepest over
-- the leaves of one collider; this picks the deepest over the terrain's colliders, by the
-- same rule, so a body across the seam between the tiles and the chain is pushed out of
-- the surface and not sideways by the shallow corner it barely touches).
local function deepest(state, body)
  local best
  for _, static in ipairs(state.statics) do
    local m = state.S.triking(static, body)
    if m and (not best or m.depth > best.depth) then best = m end
  end
  return best
end

-- Remove the part of a body's velocity that goes into the surface of normal (nx, ny).
local function stopInto(b, nx, ny)
  local vn = b.vx * nx + b.vy * ny
  if vn < 0 then b.vx, b.vy = b.vx - vn * nx, b.vy - vn * ny end
end

-- Push a body out of the terrain; remember the deepest contact for drawing.
local function resolve(state, b)
  local S = state.S
  for pass = 1, MAX_PUSHES do
    local m = deepest(state, b.body)
    if not m then break end
    if pass == 1 then b.mtv, b.contacts = m, S.ite(m) end
    -- The normal points from the terrain toward the body.
    if -m.ny > GROUND_NY then
      -- Ground: push straight up, by the height that removes the overlap along the normal
      -- (depth / -ny), and stop falling. Pushing along the normal instead would move a body
      -- standing on a slope sideways a little every step: it would creep down the slope.
      b.body:translate(0, m.depth / m.ny)
      if b.vy > 0 then b.vy = 0 end
      b.grounded = true
    else
      S.hove(m) -- walls and ceilings: the full MTV
      stopInto(b, m.nx, m.ny)
    end
  end
end

-- A body: a collider and its motion. `left`, `right`, `jump` are the keys that drive it.
local function walker(name, body, rgb, left, right, jump)
  return { name = name, body = body, rgb = rgb, vx = 0, vy = 0, grounded = false,
    keys = { left = left, right = right, jump = jump } }
end

--- The initial state: the box and the ball standing on the tiles. They are placed half a
--- pixel into the floor and resolved once (no time passes), so the screenshot of this
--- state shows their contact and its normal.
---@param S table strike @param w number @param h number
---@return table state
function M.new(S, w, h)
  local H, T = S.hapes, S.trikers
  local _, fieldH = layout.playfield(w, h)
  local tiles = T.Collider()
  for k = 0, 9 do tiles:add(H.Rectangle(TILE / 2 + k * TILE, FLOOR_Y + TILE / 2, TILE, TILE)) end
  local chain = T.Chain(HILLS)
  -- Earth under the chain, one convex quad per segment (drawn only, never tested).
  local ground = {}
  for i = 1, #HILLS / 2 - 1 do
    local x1, y1, x2, y2 = HILLS[2 * i - 1], HILLS[2 * i], HILLS[2 * i + 1], HILLS[2 * i + 2]
    ground[i] = H.ConvexPolygon(x1, y1, x2, y2, x2, fieldH, x1, fieldH)
  end
  local box = walker('box', T.Rectangle(120, FLOOR_Y - 18 + 0.5, 36, 36), BOX, 'left', 'right', 'up')
  local ball = walker('ball', T.Circle(260, FLOOR_Y - 18 + 0.5, 18), BALL, 'a', 'd', 'w')
  local state = {
    S = S, w = w, h = h, fieldH = fieldH, keys = {}, time = 0, acc = 0, showNormals = false,
    tiles = tiles, chain = chain, ground = ground, statics = { tiles, chain },
    box = box, ball = ball, walkers = { box, ball },
  }
  for _, b in ipairs(state.walkers) do resolve(state, b) end
  return state
end

-- One fixed step of the physics.
local function step(state, dt)
  local S, keys = state.S, state.keys
  for _, b in ipairs(state.walkers) do
    local dir = (keys[b.keys.right] and 1 or 0) - (keys[b.keys.left] and 1 or 0)
    local target = dir * SPEED
    local dv = (dir ~= 0 and ACCEL or BRAKE) * dt
    if b.vx < target then b.vx = math.min(target, b.vx + dv) else b.vx = math.max(target, b.vx - dv) end
    -- Walking down a slope faster than gravity pulls would leave the ground every step;
    -- a body that stood on the ground and does not jump is pulled down by up to SNAP to
    -- stay on it (undone below if there is no ground there).
    b.snap = b.grounded
    if keys[b.keys.jump] and b.grounded then b.vy, b.snap = -JUMP, false end
    b.vy = b.vy + GRAVITY * dt
    b.body:translate(b.vx * dt, b.vy * dt)
    b.grounded, b.mtv, b.contacts = false, nil, nil
    -- the window's sides are walls
    local x0, _, x1 = b.body:getBounds()
    if x0 < 0 then b.body:translate(-x0, 0); b.vx = math.max(b.vx, 0) end
    if x1 > state.w then b.body:translate(state.w - x1, 0); b.vx = math.min(b.vx, 0) end
  end
  -- The two bodies push each other apart, half each (S.ettle), and lose the velocity that
  -- brought them together (equal masses, no bounce); one on top of the other stands on it.
  local box, ball = state.box, state.ball
  local m = S.triking(box.body, ball.body)
  if m then
    S.ettle(m)
    local nx, ny = m.nx, m.ny -- from the box toward the ball
    local vrel = (ball.vx - box.vx) * nx + (ball.vy - box.vy) * ny
    if vrel < 0 then
      box.vx, box.vy = box.vx + nx * vrel / 2, box.vy + ny * vrel / 2
      ball.vx, ball.vy = ball.vx - nx * vrel / 2, ball.vy - ny * vrel / 2
    end
    if -ny > GROUND_NY then ball.grounded = true elseif ny > GROUND_NY then box.grounded = true end
  end
  -- The terrain last: it does not move, and it wins.
  for _, b in ipairs(state.walkers) do
    if b.snap then b.body:translate(0, SNAP) end
    resolve(state, b)
    if b.snap and not b.grounded then b.body:translate(0, -SNAP) end
    local _, y0 = b.body:getBounds()
    if y0 > state.h then -- fell out of the world somehow: back to the start
      b.body:translateTo(b == box and 120 or 260, 300)
      b.vx, b.vy = 0, 0
    end
  end
  state.time = state.time + dt
end

--- Advance the physics by dt, in fixed steps (at most 10 per call).
---@param state table @param dt number seconds
function M.update(state, dt)
  state.acc = math.min(state.acc + dt, 10 * M.STEP)
  while state.acc >= M.STEP do
    step(state, M.STEP)
    state.acc = state.acc - M.STEP
  end
end

---@param state table @param key string
function M.keypressed(state, key)
  state.keys[key] = true
  if key == 'n' then
    state.showNormals = not state.showNormals
  elseif key == 'r' then
    scene.reset(M, state)
  end
end

M.keyreleased = scene.keyreleased

--- Lines for the status bar.
---@param state table
---@return string[]
function M.status(state)
  local lines = {}
  for i, b in ipairs(state.walkers) do
    local x, y = b.body:getCentroid()
    local n = b.mtv and ('normal (%.2f, %.2f), depth %.2f'):format(b.mtv.nx, b.mtv.ny, b.mtv.depth) or 'no contact'
    lines[i] = ('%s at (%.0f, %.0f), %s: %s'):format(b.name, x, y, b.grounded and 'on the ground' or 'in the air', n)
  end
  return lines
end

--- Draw with a painter (util/lovepaint.lua on screen, util/probe.lua for the probes).
---@param state table @param P table
function M.paint(state, P)
  local k = 0
  for tile in state.tiles:elems() do
    k = k + 1
    P:fill(tile, TILES[(k - 1) % 2 + 1], 'tile ' .. k)
    P:outline(tile, TILE_EDGE)
  end
  for i, quad in ipairs(state.ground) do P:fill(quad, GROUND, 'ground ' .. i) end
  for i = 1, #HILLS / 2 - 1 do
    P:line(HILLS[2 * i - 1], HILLS[2 * i], HILLS[2 * i + 1], HILLS[2 * i + 2], GRASS, 3)
  end
  for _, b in ipairs(state.walkers) do
    P:fill(b.body, b.rgb, b.name)
    P:outline(b.body, OUTLINE)
  end
  if state.showNormals then
    P:norms(state.tiles, 10)
    P:norms(state.chain, 10)
  end
  for _, b in ipairs(state.walkers) do
    if b.mtv then
      P:contacts(b.contacts, 10)
      local x, y = b.body:getCentroid()
      P:arrow(x, y, x + b.mtv.nx * 32, y + b.mtv.ny * 32, NORMAL, 2)
    end
  end
end

--- Draw on screen (LÖVE only).
function M.draw(state) scene.draw(M, state) end

--- Screenshot probes of this state: the box, the ball, two tiles, the earth under the
--- hills, and background.
---@param state table
---@return table[]
function M.probes(state)
  return scene.probes(M, state, { 'box', 'ball', 'tile 1', 'tile 6', 'ground 2', 'ground 6' })
end

return M
