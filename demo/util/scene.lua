--- What the scene modules (scenes/*.lua) have in common: drawing on screen, the R reset,
--- releasing a held key and the screenshot probes. Pure Lua; `love` is touched only when
--- a scene is drawn on screen.
local ROOT = (...):match('^(.-)[^%.]+$')
local layout = require(ROOT .. 'layout')
local probe = require(ROOT .. 'probe')
local LovePainter = require(ROOT .. 'lovepaint')

local scene = {}

--- Draw scene M's state on screen (LÖVE only): M.paint with a LÖVE painter, made once.
---@param M table the scene module @param state table
function scene.draw(M, state)
  state.painter = state.painter or LovePainter.new(state.S)
  M.paint(state, state.painter)
end

--- Start scene M again: a fresh M.new state copied into `state` in place (demo/main.lua
--- holds that table), keeping the clock main.lua gave it.
---@param M table the scene module @param state table
function scene.reset(M, state)
  local fresh = M.new(state.S, state.w, state.h)
  fresh.clock = state.clock
  for k in pairs(state) do state[k] = nil end
  for k, v in pairs(fresh) do state[k] = v end
end

--- The time step of the scripted screenshot's updates (seconds).
scene.SHOT_STEP = 1 / 60

--- Bring a fresh state of scene M to the frame its scripted screenshot shows: M.SHOT_FRAMES
--- updates of scene.SHOT_STEP each (none when the scene has no SHOT_FRAMES: its initial
--- state). demo/main.lua does this before `--screenshot` draws, and the screenshot spec
--- before it takes the probes, so both see the same frame.
---@param M table the scene module @param state table a state M.new made
---@return table state
function scene.advance(M, state)
  for _ = 1, M.SHOT_FRAMES or 0 do M.update(state, scene.SHOT_STEP) end
  return state
end

--- The state scene M's scripted screenshot shows: M.new, then scene.advance.
---@param M table @param S table strike @param w number @param h number
---@return table state
function scene.shot(M, S, w, h) return scene.advance(M, M.new(S, w, h)) end

--- Advance scene M's state by dt in fixed steps of M.STEP (M.step each), at most 5 per call
--- (the platformer's and the Tiled level's update): time left over waits in state.acc.
---@param M table the scene module @param state table @param dt number seconds
function scene.fixedSteps(M, state, dt)
  state.acc = math.min(state.acc + dt, 5 * M.STEP)
  while state.acc >= M.STEP * (1 - 1e-9) do
    M.step(state, M.STEP)
    state.acc = state.acc - M.STEP
  end
end

local MOVE_KEYS = { left = true, right = true, up = true, a = true, d = true, w = true }

--- keypressed for a scene with a character (the platformer, the Tiled level): the key is
--- held in state.keys; a movement key (arrows, A, D, W) takes over from the script, P gives
--- the character back to it, B shows or hides the broadphase, R starts scene M again.
---@param M table the scene module @param state table @param key string
function scene.characterKey(M, state, key)
  state.keys[key] = true
  if MOVE_KEYS[key] then
    state.script = false
  elseif key == 'p' then
    state.script = true
  elseif key == 'b' then
    state.showBroadphase = not state.showBroadphase
  elseif key == 'r' then
    scene.reset(M, state)
  end
end

--- keyreleased for a scene that keeps the keys held down in state.keys (its keypressed
--- sets state.keys[key] = true).
---@param state table @param key string
function scene.keyreleased(state, key) state.keys[key] = nil end

--- The names of a list of bodies ({ name =, ... }), but for those named `except`.
---@param bodies table[] @param except string|nil
---@return string[]
function scene.names(bodies, except)
  local names = {}
  for _, b in ipairs(bodies) do
    if b.name ~= except then names[#names + 1] = b.name end
  end
  return names
end

--- Screenshot probes of scene M's state: one inside each body painted with one of
--- `labels` (that has room; at most `maxShapes` of them, in order), and 3 of background.
---@param M table the scene module @param state table @param labels string[]
---@param maxShapes integer|nil
---@return table[]
function scene.probes(M, state, labels, maxShapes)
  return probe.collect(M, state, labels, 3, layout, maxShapes)
end

return scene
