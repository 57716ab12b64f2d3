--- Scene 6, platformer: a capsule character walks a level with space:move, strike's
--- move-and-slide (bump-style): a row of tiles (separate bodies, seams and all), slopes of
--- 26.6 and 45 degrees, a staircase of 6-px steps and a one-way platform (one segment of an
--- S.trikers.Chain, given left to right: solid from above, passed through from below). Each
--- step of 1/60 s adds gravity to a vertical velocity and moves the character toward
--- (x + vx dt, y + vy dt) with the character options {slope = 50 degrees, snap = 4, step = 10};
--- a collision whose normal points up (ny < -0.7) is ground and resets the vertical velocity.
--- A scripted walk drives it (right, a jump onto the platform, up the slopes and stairs, and
--- back) until an arrow key takes over.
---
--- Above, a gun fires bullets (circles of radius 2) at 400 px a step into thin walls (1, 2, 3
--- and 4 px rectangles and an edge), most of them met in the middle of a step: moved with
--- space:move and the 'touch' response, each stops at its wall, stays there a moment and
--- leaves the space. None ever passes a wall; the status bar counts them.
local ROOT = (...):match('^(.-)scenes%.[^%.]+$')
local scene = require(ROOT .. 'util.scene')

local M = {}

M.name = 'Platformer'
M.help = {
  'Scripted walk: tiles, slopes, stairs, one-way platform',
  'Arrows or A, D, W: walk and jump (ends the script)',
  'P: script again   B: broadphase (S.howSpace)   R: reset',
  'Bullets: 400 px a step into 1-4 px walls and an edge',
}

M.STEP = 1 / 60            -- fixed step (s): the same motion at any frame rate
--- The scripted screenshot shows the state after this many updates of 1/60 s (see
--- util/scene.lua, advance): the character halfway up the 26.6-degree slope after walking
--- over the one-way platform, bullets in flight and stopped at every wall.
M.SHOT_FRAMES = 105
local GRAVITY = 1500       -- px/s^2, down
local SPEED = 150          -- px/s, walking
local JUMP = 600           -- px/s, up: 120 px high
M.OPTS = { slope = math.rad(50), snap = 4, step = 10 } -- the character options of space:move
M.GROUND_NY = -0.7         -- a collision normal pointing up at least this much is ground
local CHAR_W, CHAR_H = 20, 44
M.START_X = 40             -- the character's centroid at start

-- The scripted walk: turn at these x, and jump when crossing a jump point (grounded) in the
-- direction of travel.
local TURN_LEFT, TURN_RIGHT = 30, 770
local JUMPS = { { dir = 1, x = 70 }, { dir = -1, x = 190 } }

M.FLOOR = 500              -- top of the floor tiles
local BOTTOM = 540         -- bottom of the level's blocks
M.PLATFORM = { 60, 420, 200, 420 } -- the one-way platform, left to right: solid from above

M.BULLET_SPEED = 400       -- px a step
M.BULLET_R = 2
M.FIRE_EVERY = 2           -- steps between shots
M.HOLD = 90                -- steps a stopped bullet stays before it leaves the space
local GUN_X = 34           -- the muzzle
-- The lanes of the bullets and the wall across each: its left face x and thickness (0: an edge).
M.LANES = {
  { y = 150, x = 250, thick = 1 },
  { y = 178, x = 390, thick = 2 },
  { y = 206, x = 530, thick = 3 },
  { y = 234, x = 670, thick = 4 },
  { y = 262, x = 770, thick = 0 },
}
local WALL_H = 26
local SPREAD = 8           -- a bullet's height in its lane: within this of its middle

local TILES = { { 120, 104, 92 }, { 100, 88, 78 } }
local TILE_EDGE = { 60, 52, 46 }
local GROUND = { 86, 74, 62 }
local STEPS = { 140, 120, 96 }
local PLATFORM = { 110, 200, 230 }
local CHARACTER = { 200, 110, 70 }
local OUTLINE = { 215, 220, 230 }
local NORMAL = { 255, 220, 60 }
local CONTACT = { 120, 230, 120 }
local GUN = { 90, 100, 120 }
local WALL = { 230, 230, 120 }
local BULLET = { 255, 255, 255 }
local STOPPED = { 255, 120, 90 }
local TRAIL = { 150, 150, 170 }
local BROADPHASE = { 235, 238, 245 }

-- The character's filter: every body its mask lets it meet slides.
local function slide() return 'slide' end
-- The bullets': stop at the wall.
local function touch() return 'touch' end

--- The initial state: the level, the walls and the character dropped onto the first tiles
--- (one move, no time passing: it starts on the ground).
---@param S table strike @param w number @param h number
---@return table state
function M.new(S, w, h)
  local H, T = S.hapes, S.trikers
  local space = S.pace()
  local level, names = {}, {}
  -- A piece of the level: in the space (layer 'level'), drawn with `rgb` (nil: not drawn).
  local function piece(name, body, rgb)
    space:add(body, { layer = 'level' })
    names[body] = name
    level[#level + 1] = { name = name, body = body, rgb = rgb }
    return body
  end
  local F = M.FLOOR
  for k = 0, 5 do piece('tile ' .. (k + 1), H.Rectangle(20 + 40 * k, F + 20, 40, 40), TILES[k % 2 + 1]) end
  piece('slope 26.6°', H.ConvexPolygon(240, F, 360, F - 60, 360, BOTTOM, 240, BOTTOM), GROUND)
  piece('plateau 1', H.Rectangle(380, (F - 60 + BOTTOM) / 2, 40, BOTTOM - F + 60), TILES[1])
  piece('plateau 2', H.Rectangle(420, (F - 60 + BOTTOM) / 2, 40, BOTTOM - F + 60), TILES[2])
  piece('slope 45°', H.ConvexPolygon(440, F - 60, 500, F, 500, BOTTOM, 440, BOTTOM), GROUND)
  piece('tile 7', H.Rectangle(520, F + 20, 40, 40), TILES[1])
  piece('tile 8', H.Rectangle(560, F + 20, 40, 40), TILES[2])
  for k = 1, 6 do -- 16 px deep, 6 px high each
    local top = F - 6 * k
    piece('step ' .. k, H.Rectangle(572 + 16 * k, (top + BOTTOM) / 2, 16, BOTTOM - top), STEPS)
  end
  for k = 0, 3 do -- the upper floor, 4 tiles 31 px wide
    piece('tile ' .. (9 + k), H.Rectangle(691.5 + 31 * k, (F - 36 + BOTTOM) / 2, 31, BOTTOM - F + 36),
      TILES[k % 2 + 1])
  end
  local P = M.PLATFORM
  piece('one-way platform', T.Chain(P[1], P[2], P[3], P[4]), nil)
  piece('left wall', H.Rectangle(-20, 300, 40, 600), nil)  -- the window's sides, not drawn
  piece('right wall', H.Rectangle(w + 20, 300, 40, 600), nil)
  local walls = {}
  for i, lane in ipairs(M.LANES) do
    local body
    if lane.thick > 0 then
      body = H.Rectangle(lane.x + lane.thick / 2, lane.y, lane.thick, WALL_H)
    else
      body = H.Edge(lane.x, lane.y - WALL_H / 2, lane.x, lane.y + WALL_H / 2)
    end
    space:add(body, { layer = 'wall' })
    local label = lane.thick > 0 and ('%d px wall'):format(lane.thick) or 'edge'
    walls[i] = { name = label, body = body }
    names[body] = label
  end
  local gun = H.Rectangle(22, (M.LANES[1].y + M.LANES[#M.LANES].y) / 2, 24, M.LANES[#M.LANES].y - M.LANES[1].y + 24)
  local character = space:add(H.Capsule(M.START_X, F - CHAR_H / 2 - 1, CHAR_W, CHAR_H),
    { layer = 'player', mask = { 'level' } })
  local state = {
    S = S, w = w, h = h, space = space, level = level, names = names, walls = walls, gun = gun,
    character = character, vx = 0, vy = 0, dir = 1, script = true, keys = {}, acc = 0,
    grounded = false, ground = nil, contacts = {}, moveCount = 0, touched = {},
    bullets = {}, showBroadphase = false,
    stats = { steps = 0, fired = 0, stopped = 0, passed = 0, inFlight = 0 },
  }
  M.moveCharacter(state, 0, 1)
  return state
end

--- Move the character by (dx, dy) with space:move and its options; note the collisions (their
--- contact points and normals, for drawing), whether it stands on the ground and on what.
---@param state table @param dx number @param dy number
function M.moveCharacter(state, dx, dy)
  local c = state.character
  local x, y = c:getCentroid()
  local _, _, cols, n = state.space:move(c, x + dx, y + dy, slide, M.OPTS)
  state.grounded, state.ground, state.moveCount = false, nil, n
  local contacts = state.contacts
  for i = 1, n do
    local col = cols[i] -- (the space's records, reused by the next move: copied)
    local rec = contacts[i] or {}
    rec.x, rec.y, rec.nx, rec.ny, rec.other = col.x, col.y, col.nx, col.ny, col.other
    contacts[i] = rec
    if col.ny < M.GROUND_NY then
      state.grounded, state.ground = true, col.other
      state.touched[state.names[col.other]] = true
      if state.vy > 0 then state.vy = 0 end
    elseif col.ny > -M.GROUND_NY and state.vy < 0 then
      state.vy = 0 -- a ceiling
    end
  end
  for i = #contacts, n + 1, -1 do contacts[i] = nil end
end

-- The scripted walk's input: the direction (-1, 0, 1) and whether to jump.
local function scripted(state)
  local x = state.character:getCentroid()
  if state.dir > 0 and x >= TURN_RIGHT then
    state.dir = -1
  elseif state.dir < 0 and x <= TURN_LEFT then
    state.dir = 1
  end
  local nextX = x + state.dir * SPEED * M.STEP
  local jump = false
  for _, j in ipairs(JUMPS) do
    if j.dir == state.dir and (x - j.x) * j.dir < 0 and (nextX - j.x) * j.dir >= 0 then jump = true end
  end
  return state.dir, jump
end

-- The player's input, from the keys held.
local function held(state)
  local k = state.keys
  local dir = ((k.right or k.d) and 1 or 0) - ((k.left or k.a) and 1 or 0)
  return dir, (k.up or k.w) and true or false
end

-- One step of the character: input, gravity, one move.
local function stepCharacter(state, dt)
  local dir, jump
  if state.script then dir, jump = scripted(state) else dir, jump = held(state) end
  state.vx = dir * SPEED
  if jump and state.grounded then state.vy = -JUMP end
  state.vy = state.vy + GRAVITY * dt
  M.moveCharacter(state, state.vx * dt, state.vy * dt)
  local _, y0 = state.character:getBounds()
  if y0 > state.h then -- (fell out of the world somehow: back to the start)
    state.character:translateTo(M.START_X, 300)
    state.vy = 0
  end
end

-- A new bullet at the muzzle, in the next lane in turn, a little off its middle.
local function fire(state)
  local stats = state.stats
  stats.fired = stats.fired + 1
  local k = stats.fired
  local lane = (k - 1) % #M.LANES + 1
  local y = M.LANES[lane].y + (k * 5) % (2 * SPREAD + 1) - SPREAD
  local body = state.S.hapes.Circle(GUN_X + M.BULLET_R, y, M.BULLET_R)
  state.space:add(body, { layer = 'bullet', mask = { 'wall' } })
  state.bullets[#state.bullets + 1] = { body = body, lane = lane, fromX = GUN_X + M.BULLET_R, hold = nil }
end

-- One step of the bullets: fire, move those in flight (a bullet that stops keeps the
-- trail of its last leg for a step), count down those stopped and take them away.
local function stepBullets(state)
  local stats, space = state.stats, state.space
  if stats.steps % M.FIRE_EVERY == 0 then fire(state) end
  local kept, flying = {}, 0
  for _, b in ipairs(state.bullets) do
    local x, y = b.body:getCentroid()
    b.fromX = x
    local keep = true
    if b.hold then
      b.hold = b.hold - 1
      keep = b.hold > 0
    else
      local ax, _, _, n = space:move(b.body, x + M.BULLET_SPEED, y, touch)
      if ax + M.BULLET_R > M.LANES[b.lane].x + 1e-6 then -- past its wall's face: it tunnelled
        stats.passed = stats.passed + 1
        keep = false
      elseif n > 0 then
        stats.stopped = stats.stopped + 1
        b.hold = M.HOLD
      else
        flying = flying + 1
      end
    end
    if keep then kept[#kept + 1] = b else space:remove(b.body) end
  end
  state.bullets = kept
  stats.inFlight = flying
end

--- One fixed step: the character, then the bullets.
---@param state table @param dt number seconds
function M.step(state, dt)
  stepCharacter(state, dt)
  stepBullets(state)
  state.stats.steps = state.stats.steps + 1
end

--- Advance by dt, in fixed steps (at most 5 per call).
---@param state table @param dt number seconds
function M.update(state, dt) scene.fixedSteps(M, state, dt) end

---@param state table @param key string
function M.keypressed(state, key) scene.characterKey(M, state, key) end

M.keyreleased = scene.keyreleased

--- Lines for the status bar.
---@param state table
---@return string[]
function M.status(state)
  local x, y = state.character:getCentroid()
  local s = state.stats
  return {
    ('character at (%.0f, %.0f), on ground: %s; last move: %d collisions; %s'):format(x, y,
      state.grounded and ('yes (%s)'):format(state.names[state.ground]) or 'no', state.moveCount,
      state.script and 'scripted walk' or 'your keys'),
    ('bullets at %d px a step: %d fired, %d in flight, bullets stopped: %d, passed: %d'):format(M.BULLET_SPEED,
      s.fired, s.inFlight, s.stopped, s.passed),
  }
end

--- Draw with a painter (util/lovepaint.lua on screen, util/probe.lua for the probes).
---@param state table @param P table
function M.paint(state, P)
  for _, p in ipairs(state.level) do
    if p.rgb then
      P:fill(p.body, p.rgb, p.name)
      P:outline(p.body, TILE_EDGE)
    end
  end
  local pf = M.PLATFORM
  P:line(pf[1], pf[2], pf[3], pf[4], PLATFORM, 3)
  P:fill(state.gun, GUN, 'gun')
  P:outline(state.gun, OUTLINE)
  for _, wall in ipairs(state.walls) do P:fill(wall.body, WALL, wall.name) end
  for _, b in ipairs(state.bullets) do
    local x, y = b.body:getCentroid()
    if b.fromX ~= x then P:line(b.fromX, y, x, y, TRAIL, 1) end
    P:fill(b.body, b.hold and STOPPED or BULLET)
  end
  P:fill(state.character, CHARACTER, 'character')
  P:outline(state.character, OUTLINE)
  -- each collision of the last move: its contact point, and its normal as an arrow from
  -- the other body toward the character
  for _, c in ipairs(state.contacts) do
    P:arrow(c.x - c.nx * 18, c.y - c.ny * 18, c.x, c.y, NORMAL, 2)
    P:disc(c.x, c.y, 2.5, CONTACT)
  end
  if state.showBroadphase then P:space(state.space, BROADPHASE) end
end

--- Draw on screen (LÖVE only).
function M.draw(state) scene.draw(M, state) end

--- Screenshot probes of this state: the character, pieces of the level, the gun, and
--- background.
---@param state table
---@return table[]
function M.probes(state)
  return scene.probes(M, state, { 'character', 'tile 1', 'slope 26.6°', 'plateau 2', 'slope 45°', 'step 6',
    'tile 11', 'gun' })
end

return M
