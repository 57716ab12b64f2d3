--- Scene 2, rays: a fan of rays cast from the mouse against a set of bodies, each drawn up
--- to its first hit with the normal there (S.howRay). A click fixes a target instead: one
--- ray toward it, with every boundary crossing along it (collider:rayIntersections).
---
--- The bodies are the children of one `world` collider, so one rayCast answers for all of
--- them and reports the leaf shape hit first. (Members of a collider never collide with
--- each other; this scene only casts rays, so that costs nothing.)
local ROOT = (...):match('^(.-)scenes%.[^%.]+$')
local scene = require(ROOT .. 'util.scene')

local M = {}

M.name = 'Rays'
M.help = {
  'Move the mouse: rays from the pointer    +/-: more/fewer',
  'Left click: aim at a target    Right click or Space: fan',
  'R: spin the bodies on/off',
}

local OUTLINE = { 215, 220, 230 }
local CROSSING = { 255, 255, 255 }
local TARGET = { 255, 200, 60 }
local MIN_RAYS, MAX_RAYS, STEP_RAYS = 8, 256, 8

--- The initial state: eight bodies, 48 rays from a point in the open.
---@param S table strike @param w number @param h number
---@return table state
function M.new(S, w, h)
  local T = S.trikers
  local bodies = {
    { name = 'circle', body = T.Circle(600, 165, 50), rgb = { 150, 100, 190 }, spin = 0.3 },
    { name = 'rectangle', body = T.Rectangle(665, 330, 130, 60, 0.4), rgb = { 60, 150, 120 }, spin = -0.5 },
    { name = 'hexagon', body = T.RegularPolygon(250, 240, 6, 55), rgb = { 70, 120, 190 }, spin = 0.4 },
    { name = 'L block', body = T.Concave(90, 330, 210, 330, 210, 375, 140, 375, 140, 480, 90, 480),
      rgb = { 190, 150, 60 }, spin = -0.3 },
    { name = 'capsule', body = T.Capsule(470, 470, 50, 150, 1.2), rgb = { 170, 90, 120 }, spin = 0.6 },
    { name = 'edge', body = T.Edge(250, 520, 360, 420), rgb = { 230, 230, 120 }, spin = 0.8 },
    { name = 'ellipse', body = T.Ellipse(660, 480, 80, 40, 24), rgb = { 60, 140, 170 }, spin = -0.4 },
    { name = 'triangle', body = T.ConvexPolygon(405, 150, 500, 190, 400, 240), rgb = { 120, 130, 80 }, spin = 0.5 },
  }
  local world = T.Collider()
  for _, b in ipairs(bodies) do world:add(b.body) end
  return {
    S = S, w = w, h = h,
    bodies = bodies, world = world,
    originX = 420, originY = 330, rays = 48,
    target = nil, spinning = false,
  }
end

--- Spin the bodies when asked to.
---@param state table @param dt number
function M.update(state, dt)
  if not state.spinning then return end
  for _, b in ipairs(state.bodies) do b.body:rotate(b.spin * dt) end
end

---@param state table @param x number @param y number
function M.mousemoved(state, x, y)
  state.originX, state.originY = x, y
end

--- Left button: aim at this point; right button: back to the fan.
---@param state table @param x number @param y number @param button integer
function M.mousepressed(state, x, y, button)
  if button == 1 then
    state.target = { x = x, y = y }
  elseif button == 2 then
    state.target = nil
  end
end

---@param state table @param key string
function M.keypressed(state, key)
  if key == 'space' then
    state.target = nil
  elseif key == 'r' then
    state.spinning = not state.spinning
  elseif key == '+' or key == '=' or key == 'kp+' then
    state.rays = math.min(MAX_RAYS, state.rays + STEP_RAYS)
  elseif key == '-' or key == 'kp-' then
    state.rays = math.max(MIN_RAYS, state.rays - STEP_RAYS)
  end
end

-- The direction of ray k of the fan (k = 0 .. n-1).
local function fanDirection(k, n)
  local a = (k + 0.5) * 2 * math.pi / n
  return math.cos(a), math.sin(a)
end

-- The aimed ray's direction, or nil when the target is the origin itself.
local function aim(state)
  local dx, dy = state.target.x - state.originX, state.target.y - state.originY
  if dx == 0 and dy == 0 then return nil end
  return dx, dy
end

-- The aimed ray's crossings with every leaf, as points, nearest first.
local function crossings(state)
  local dx, dy = aim(state)
  local points = {}
  if not dx then return points end
  local l = math.sqrt(dx * dx + dy * dy)
  local hits = state.world:rayIntersections(state.originX, state.originY, dx, dy)
  for _, ts in pairs(hits or {}) do
    for _, t in ipairs(ts) do points[#points + 1] = t end
  end
  table.sort(points)
  for i, t in ipairs(points) do
    points[i] = { t = t, x = state.originX + dx / l * t, y = state.originY + dy / l * t }
  end
  return points
end

--- Lines for the status bar.
---@param state table
---@return string[]
function M.status(state)
  local ox, oy = state.originX, state.originY
  if state.target then
    local dx, dy = aim(state)
    local t = dx and state.world:rayCast(ox, oy, dx, dy)
    return {
      ('Ray from (%.0f, %.0f) toward (%.0f, %.0f)'):format(ox, oy, state.target.x, state.target.y),
      ('%d boundary crossings; first hit %s'):format(#crossings(state), t and ('at distance %.1f'):format(t) or 'none'),
    }
  end
  local hits, nearest = 0, nil
  for k = 0, state.rays - 1 do
    local t = state.world:rayCast(ox, oy, fanDirection(k, state.rays))
    if t then
      hits = hits + 1
      if not nearest or t < nearest then nearest = t end
    end
  end
  return {
    ('%d rays from (%.0f, %.0f): %d hit'):format(state.rays, ox, oy, hits),
    nearest and ('nearest hit at distance %.1f'):format(nearest) or 'no hit',
  }
end

--- Draw with a painter (util/lovepaint.lua on screen, util/probe.lua for the probes).
---@param state table @param P table
function M.paint(state, P)
  for _, b in ipairs(state.bodies) do
    P:fill(b.body, b.rgb, b.name)
    P:outline(b.body, OUTLINE)
  end
  local ox, oy = state.originX, state.originY
  if state.target then
    local dx, dy = aim(state)
    if dx then
      P:ray(state.world, ox, oy, dx, dy)
      for _, p in ipairs(crossings(state)) do P:disc(p.x, p.y, 2, CROSSING) end
    end
    P:line(state.target.x - 6, state.target.y, state.target.x + 6, state.target.y, TARGET, 2)
    P:line(state.target.x, state.target.y - 6, state.target.x, state.target.y + 6, TARGET, 2)
  else
    for k = 0, state.rays - 1 do
      local dx, dy = fanDirection(k, state.rays)
      P:ray(state.world, ox, oy, dx, dy)
    end
  end
  P:disc(ox, oy, 4, TARGET)
end

--- Draw on screen (LÖVE only).
function M.draw(state) scene.draw(M, state) end

--- Screenshot probes of this state: inside the bodies with an area, and background.
function M.probes(state) return scene.probes(M, state, scene.names(state.bodies, 'edge')) end

return M
