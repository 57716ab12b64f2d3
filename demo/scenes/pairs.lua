--- Scene 1, shape pairs: a few shapes and colliders to drag and turn with the mouse. Every
--- pair is tested with S.triking each frame; colliding bodies change colour and show their
--- MTV (S.howMTV), contact points and normal (S.ite + S.howContacts), their shapes' normals
--- (S.howNorms) and, on request, the projections on the MTV's axis (S.howProj).
local ROOT = (...):match('^(.-)scenes%.[^%.]+$')
local geom = require(ROOT .. 'util.geom')
local scene = require(ROOT .. 'util.scene')

local M = {}

M.name = 'Shape pairs'
M.help = {
  'Left drag: move a shape     Right drag or wheel: turn it',
  'Q / E (held): turn the shape under the mouse',
  'N: normals on/off   P: projections on/off   R: reset',
}

local OUTLINE = { 215, 220, 230 }
local TURN_SPEED = 2.5    -- radians per second while Q or E is held
local PICK_DISTANCE = 8   -- how close to an edge counts as grabbing it

-- A body's colour while it collides with something: a warmer, brighter variant.
local function hot(rgb)
  return { math.min(255, rgb[1] + 110), math.floor(rgb[2] * 0.55), math.floor(rgb[3] * 0.45) }
end

-- Test every pair; remember the collisions for drawing.
local function collide(state)
  local S = state.S
  state.hits, state.colliding = {}, {}
  local bodies = state.bodies
  for i = 1, #bodies do
    for j = i + 1, #bodies do
      local mtv = S.triking(bodies[i].body, bodies[j].body)
      if mtv then
        state.hits[#state.hits + 1] = { mtv = mtv, contacts = S.ite(mtv) }
        state.colliding[bodies[i]], state.colliding[bodies[j]] = true, true
      end
    end
  end
end

--- The initial state: four pairs (polygon and rectangle, circle and capsule, ellipse and
--- edge, compound collider and hexagon), the first three overlapping, and a rectangle with
--- rounded corners on its own.
---@param S table strike @param w number window width @param h number window height
---@return table state
function M.new(S, w, h)
  local H, T = S.hapes, S.trikers
  local function body(name, b, rgb) return { name = name, body = b, rgb = rgb } end
  local state = {
    S = S, w = w, h = h, keys = {}, mouseX = w / 2, mouseY = h / 2,
    showNormals = true, showProj = false,
    bodies = {
      body('pentagon', T.ConvexPolygon(470, 150, 560, 165, 575, 250, 495, 285, 440, 225), { 70, 120, 190 }),
      body('rectangle', T.Rectangle(625, 235, 140, 70, 0.35), { 60, 150, 120 }),
      body('circle', T.Circle(120, 330, 60), { 150, 100, 190 }),
      body('capsule', T.Capsule(215, 345, 60, 180, -0.45), { 190, 150, 60 }),
      body('ellipse', T.Ellipse(440, 430, 100, 50, 24), { 60, 140, 170 }),
      body('edge', T.Edge(330, 370, 500, 520), { 230, 230, 120 }),
      body('compound', T.Collider(H.Rectangle(655, 420, 130, 36), H.Rectangle(655, 470, 36, 70),
        H.Circle(700, 470, 22)), { 120, 130, 80 }),
      body('hexagon', T.RegularPolygon(590, 340, 6, 50, 0.2), { 170, 90, 120 }),
      body('rounded box', T.Rectangle(250, 185, 110, 60, 0.2, 14), { 90, 160, 200 }),
    },
  }
  collide(state)
  return state
end

-- The body under (x, y): the topmost one containing it, else the nearest within reach.
local function bodyAt(state, x, y)
  local best, bestD
  for i = #state.bodies, 1, -1 do
    local b = state.bodies[i]
    local d = geom.pickDistance(b.body, x, y)
    if d == 0 then return b end
    if d <= PICK_DISTANCE and (not bestD or d < bestD) then best, bestD = b, d end
  end
  return best
end

--- Turn the shape held by Q or E, and test every pair again.
---@param state table @param dt number seconds
function M.update(state, dt)
  local turn = (state.keys.e and 1 or 0) - (state.keys.q and 1 or 0)
  if turn ~= 0 then
    local b = bodyAt(state, state.mouseX, state.mouseY) or state.selected
    if b then
      state.selected = b
      b.body:rotate(turn * TURN_SPEED * dt)
    end
  end
  collide(state)
end

--- Left button: start dragging the body under the mouse; right button: start turning it.
---@param state table @param x number @param y number @param button integer
function M.mousepressed(state, x, y, button)
  state.mouseX, state.mouseY = x, y
  local b = bodyAt(state, x, y)
  if not b then return end
  state.selected = b
  if button == 1 then
    state.drag = { b = b, x = x, y = y }
  elseif button == 2 then
    state.turn = { b = b, x = x }
  end
end

---@param state table @param x number @param y number
function M.mousemoved(state, x, y)
  state.mouseX, state.mouseY = x, y
  if state.drag then
    state.drag.b.body:translate(x - state.drag.x, y - state.drag.y)
    state.drag.x, state.drag.y = x, y
  end
  if state.turn then
    state.turn.b.body:rotate((x - state.turn.x) * 0.01)
    state.turn.x = x
  end
  if state.drag or state.turn then collide(state) end
end

---@param state table @param button integer
function M.mousereleased(state, _, _, button)
  if button == 1 then state.drag = nil elseif button == 2 then state.turn = nil end
end

--- The wheel turns the body under the mouse (or the last one touched).
---@param state table @param dy number
function M.wheelmoved(state, _, dy)
  local b = bodyAt(state, state.mouseX, state.mouseY) or state.selected
  if b then
    state.selected = b
    b.body:rotate(dy * 0.15)
    collide(state)
  end
end

---@param state table @param key string
function M.keypressed(state, key)
  state.keys[key] = true
  if key == 'n' then
    state.showNormals = not state.showNormals
  elseif key == 'p' then
    state.showProj = not state.showProj
  elseif key == 'r' then
    scene.reset(M, state)
  end
end

M.keyreleased = scene.keyreleased

--- Lines for the status bar.
---@param state table
---@return string[]
function M.status(state)
  local depths = {}
  for i, hit in ipairs(state.hits) do depths[i] = ('%.1f'):format(hit.mtv.depth) end
  return {
    ('%d collisions (depths %s)'):format(#state.hits, #depths > 0 and table.concat(depths, ', ') or '-'),
    ('normals %s, projections %s'):format(state.showNormals and 'on' or 'off', state.showProj and 'on' or 'off'),
  }
end

--- Draw with a painter (util/lovepaint.lua on screen, util/probe.lua for the probes).
---@param state table @param P table
function M.paint(state, P)
  for _, b in ipairs(state.bodies) do
    P:fill(b.body, state.colliding[b] and hot(b.rgb) or b.rgb, b.name)
    P:outline(b.body, OUTLINE)
  end
  if state.showNormals then
    for _, b in ipairs(state.bodies) do P:norms(b.body, 12) end
  end
  for _, hit in ipairs(state.hits) do
    P:mtv(hit.mtv)
    P:contacts(hit.contacts, 15)
    if state.showProj then P:proj(hit.mtv) end
  end
end

--- Draw on screen (LÖVE only).
function M.draw(state) scene.draw(M, state) end

--- Screenshot probes of this state: inside every body with an area, and background.
function M.probes(state) return scene.probes(M, state, scene.names(state.bodies, 'edge')) end

return M
