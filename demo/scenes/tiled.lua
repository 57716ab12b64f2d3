--- Scene 7, a level from Tiled: demo/maps/level.lua, a map in the format of Tiled's Lua export
--- (written for this demo), loaded with S.tiled into an S.pace: the tile layer's solid tiles
--- merged into one body per connected region (the ground, with two holes under it, is one
--- body of 9 rectangles, drawn with their outlines), the slope tiles (a collision triangle
--- drawn in Tiled's tile collision editor, flipped for the way down) as bodies of their own, a
--- one-way platform (a polyline with oneway = true), a boulder (a round ellipse: a circle), a
--- concave rock, a turned plank, a crate (a tile object), and coins (ellipses on a sensor
--- layer). A capsule character walks it with space:move and the character options, on a
--- scripted walk (jumping onto the platform, and over whatever stops it) until an arrow key
--- takes over; it picks up the coins it touches (space:queryShape with a filter on their
--- layer).
local ROOT = (...):match('^(.-)scenes%.[^%.]+$')
local scene = require(ROOT .. 'util.scene')
local MAP = require(ROOT .. 'maps.level')

local M = {}

M.name = 'Tiled level'
M.help = {
  'demo/maps/level.lua, a Tiled Lua export, via S.tiled',
  'Scripted walk; arrows or A, D, W: walk and jump',
  'P: script again   B: broadphase (S.howSpace)   R: reset',
  'Coins: sensors on layer coin, picked up by queryShape',
}

M.STEP = 1 / 60
--- The scripted screenshot: the character past the one-way platform, on the hill, with the
--- first coins picked up.
M.SHOT_FRAMES = 150
local GRAVITY, SPEED, JUMP = 1500, 150, 600 -- px/s^2, px/s, px/s (a jump 120 px high)
M.OPTS = { slope = math.rad(50), snap = 6, step = 8 }
M.GROUND_NY = -0.7
local CHAR_W, CHAR_H = 20, 44
local TURN_LEFT, TURN_RIGHT = 30, 760
M.JUMP_AT = 56 -- the scripted walk jumps here going right: onto the one-way platform

local COLOURS = {
  ground = { 120, 96, 70 }, grass = { 120, 96, 70 }, brick = { 170, 80, 60 }, slope = { 96, 150, 80 },
  boulder = { 130, 130, 140 }, rock = { 110, 100, 130 }, plank = { 180, 150, 90 }, crate = { 200, 140, 60 },
  cloud = { 90, 110, 150 }, platform = { 110, 200, 230 }, coin = { 250, 215, 60 },
}
local EDGE = { 60, 48, 40 }
local CHARACTER = { 200, 110, 70 }
local OUTLINE = { 215, 220, 230 }
local BROADPHASE = { 235, 238, 245 }

local function slide() return 'slide' end

-- What a body of the level is called: a region or tile by its tile's `kind` property, an
-- object by its name.
local function nameOf(level, body)
  local o = level.objectOf[body]
  if o.tiles then return o.tile and o.tile.properties.kind or 'tile' end
  return o.name
end

-- The map's spawn point: the point named 'spawn' on the layer 'markers' (not collidable: the
-- game reads it from the map itself).
local function spawnPoint(map)
  for _, layer in ipairs(map.layers) do
    if layer.name == 'markers' then
      for _, o in ipairs(layer.objects) do
        if o.name == 'spawn' then return o.x, o.y end
      end
    end
  end
  error('demo/maps/level.lua has no spawn point')
end

--- The initial state: the level loaded into a space, and the character dropped onto the
--- ground at the spawn point.
---@param S table strike @param w number @param h number
---@return table state
function M.new(S, w, h)
  local space = S.pace()
  local level = S.tiled(MAP, space)
  local pieces, coins, tiles, tileBodies = {}, {}, 0, 0
  for _, body in ipairs(level.bodies) do
    local name = nameOf(level, body)
    local o = level.objectOf[body]
    if o.tiles then tiles, tileBodies = tiles + o.tiles, tileBodies + 1 end
    if name == 'coin' then
      coins[#coins + 1] = body
    else
      pieces[#pieces + 1] = { name = name, body = body, rgb = COLOURS[name] or COLOURS.ground }
    end
  end
  local sx, sy = spawnPoint(MAP)
  local character = space:add(S.hapes.Capsule(sx, sy - CHAR_H / 2, CHAR_W, CHAR_H), { layer = 'player',
    mask = { 'level' } })
  local state = {
    S = S, w = w, h = h, space = space, level = level, pieces = pieces, coins = coins, coinCount = #coins,
    tiles = tiles, tileBodies = tileBodies, character = character, vx = 0, vy = 0, dir = 1, script = true, keys = {},
    acc = 0, grounded = false, blocked = false, picked = 0, steps = 0, showBroadphase = false,
  }
  M.moveCharacter(state, 0, 2 * CHAR_H) -- (onto the ground below the spawn point)
  return state
end

local isCoin = { mask = { 'coin' } }

--- Move the character by (dx, dy) with space:move: whether it stands on the ground (and on
--- what) and whether a wall stopped it; then pick up the coins it touches.
---@param state table @param dx number @param dy number
function M.moveCharacter(state, dx, dy)
  local c, space = state.character, state.space
  local x, y = c:getCentroid()
  local _, _, cols, n = space:move(c, x + dx, y + dy, slide, M.OPTS)
  state.grounded, state.blocked, state.ground = false, false, nil
  for i = 1, n do
    local col = cols[i]
    if col.ny < M.GROUND_NY then
      state.grounded, state.ground = true, col.other
      if state.vy > 0 then state.vy = 0 end
    elseif col.ny > -M.GROUND_NY and state.vy < 0 then
      state.vy = 0 -- a ceiling
    elseif dx ~= 0 and col.nx * dx < 0 and math.abs(col.nx) > 0.7 then
      state.blocked = true
    end
  end
  local touched, k = space:queryShape(c, isCoin)
  for i = 1, k do
    space:remove(touched[i])
    state.picked = state.picked + 1
  end
end

-- The scripted walk: turn at the ends, jump onto the platform, and jump over what stops it.
local function scripted(state)
  local x = state.character:getCentroid()
  if state.dir > 0 and x >= TURN_RIGHT then
    state.dir = -1
  elseif state.dir < 0 and x <= TURN_LEFT then
    state.dir = 1
  end
  local nextX = x + state.dir * SPEED * M.STEP
  local jump = state.blocked or (state.dir > 0 and x < M.JUMP_AT and nextX >= M.JUMP_AT)
  return state.dir, jump
end

local function held(state)
  local k = state.keys
  local dir = ((k.right or k.d) and 1 or 0) - ((k.left or k.a) and 1 or 0)
  return dir, (k.up or k.w) and true or false
end

--- One fixed step: input, gravity, one move.
---@param state table @param dt number seconds
function M.step(state, dt)
  local dir, jump
  if state.script then dir, jump = scripted(state) else dir, jump = held(state) end
  state.vx = dir * SPEED
  if jump and state.grounded then state.vy = -JUMP end
  state.vy = state.vy + GRAVITY * dt
  M.moveCharacter(state, state.vx * dt, state.vy * dt)
  local _, y0 = state.character:getBounds()
  if y0 > state.h then -- (fell out of the world somehow: back to the spawn point)
    local sx, sy = spawnPoint(MAP)
    state.character:translateTo(sx, sy - CHAR_H / 2)
    state.vy = 0
  end
  state.steps = state.steps + 1
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
  return {
    ('S.tiled: %d bodies: %d from %d tiles, %d objects (%d coins); coins picked up: %d'):format(
      #state.level.bodies, state.tileBodies, state.tiles, #state.level.bodies - state.tileBodies, state.coinCount,
      state.picked),
    ('character at (%.0f, %.0f), on ground: %s; %s'):format(x, y, state.grounded and 'yes' or 'no',
      state.script and 'scripted walk' or 'your keys'),
  }
end

--- Draw with a painter (util/lovepaint.lua on screen, util/probe.lua for the probes).
---@param state table @param P table
function M.paint(state, P)
  for _, p in ipairs(state.pieces) do
    P:fill(p.body, p.rgb, p.name)
    if p.name ~= 'platform' then P:outline(p.body, EDGE) end
  end
  for _, coin in ipairs(state.coins) do
    if state.space:has(coin) then P:fill(coin, COLOURS.coin, 'coin') end
  end
  P:fill(state.character, CHARACTER, 'character')
  P:outline(state.character, OUTLINE)
  if state.showBroadphase then P:space(state.space, BROADPHASE) end
end

--- Draw on screen (LÖVE only).
function M.draw(state) scene.draw(M, state) end

--- Screenshot probes: the character, the ground region, a slope, the bricks, the objects and
--- a coin, and background.
---@param state table
---@return table[]
function M.probes(state)
  return scene.probes(M, state, { 'character', 'ground', 'slope', 'brick', 'boulder', 'rock', 'plank', 'crate',
    'cloud', 'coin' })
end

return M
