--- Scene 3, concave polygons: click an outline point by point and close it; it becomes an
--- S.trikers.Concave, drawn as its convex pieces in distinct colours. An outline the
--- library refuses (self-intersecting, spiky, too few points...) shows the library's own
--- error message instead: the constructor is called under pcall.
local ROOT = (...):match('^(.-)scenes%.[^%.]+$')
local scene = require(ROOT .. 'util.scene')

local M = {}

M.name = 'Concave'
M.help = {
  'Left click: add a point    Right click or Enter: close',
  'C or Backspace: clear    X: the example outline again',
  'The pieces are the convex parts strike splits it into',
}

local PALETTE = {
  { 70, 120, 190 }, { 60, 150, 120 }, { 190, 150, 60 }, { 170, 90, 120 },
  { 150, 100, 190 }, { 60, 140, 170 }, { 120, 130, 80 }, { 200, 110, 70 },
}
local PIECE_EDGE = { 30, 32, 40 }
local OUTLINE = { 235, 238, 245 }
local DRAFT = { 255, 200, 60 }
local REFUSED = { 255, 110, 100 }

-- A crown with a notch in its base: concave at five vertices.
local EXAMPLE = { 170, 480, 170, 250, 270, 345, 370, 190, 470, 345, 570, 250, 610, 480, 430, 480, 390, 420, 350, 480 }

-- Build the outline's Concave collider, or keep the library's error message.
local function build(state, points)
  state.outline = points
  local ok, result = pcall(state.S.trikers.Concave, points)
  if ok then
    state.poly, state.error = result, nil
  else
    -- strike raises at the caller's line; the "file:line:" part says nothing to a player
    state.poly, state.error = nil, (tostring(result):gsub('^.-:%d+: ', ''))
  end
end

--- The initial state: the example outline, built.
---@param S table strike @param w number @param h number
---@return table state
function M.new(S, w, h)
  local state = { S = S, w = w, h = h, draft = {}, mouseX = nil, mouseY = nil }
  local points = {}
  for i, v in ipairs(EXAMPLE) do points[i] = v end
  build(state, points)
  return state
end

--- Nothing moves here.
function M.update() end

--- Close the outline being drawn (if it has any point) and build it.
---@param state table
function M.close(state)
  if #state.draft == 0 then return end
  local points = state.draft
  state.draft = {}
  build(state, points)
end

---@param state table @param x number @param y number @param button integer
function M.mousepressed(state, x, y, button)
  if button == 1 then
    if #state.draft == 0 then state.poly, state.outline, state.error = nil, nil, nil end
    state.draft[#state.draft + 1] = x
    state.draft[#state.draft + 1] = y
  elseif button == 2 then
    M.close(state)
  end
end

---@param state table @param x number @param y number
function M.mousemoved(state, x, y)
  state.mouseX, state.mouseY = x, y
end

---@param state table @param key string
function M.keypressed(state, key)
  if key == 'return' or key == 'kpenter' then
    M.close(state)
  elseif key == 'c' or key == 'backspace' then
    state.draft, state.poly, state.outline, state.error = {}, nil, nil, nil
  elseif key == 'x' then
    state.draft = {}
    local points = {}
    for i, v in ipairs(EXAMPLE) do points[i] = v end
    build(state, points)
  end
end

--- Lines for the status bar; an error is { text =, error = true }.
---@param state table
---@return table
function M.status(state)
  local lines = {}
  if state.error then
    lines[1] = { text = state.error, error = true }
  elseif state.poly then
    lines[1] = ('%d points, %d convex pieces, area %.0f'):format(#state.outline / 2, state.poly:getShapeCount(),
      state.poly:getArea())
  else
    lines[1] = 'Click to add points'
  end
  if #state.draft > 0 then
    lines[2] = ('Drawing: %d points (right click or Enter closes)'):format(#state.draft / 2)
  end
  return lines
end

-- The polyline through a flat point list, closed or not.
local function polyline(P, pts, rgb, closed, width)
  local n = #pts / 2
  for i = 1, closed and n or n - 1 do
    local j = i % n + 1
    P:line(pts[2 * i - 1], pts[2 * i], pts[2 * j - 1], pts[2 * j], rgb, width)
  end
  for i = 1, n do P:disc(pts[2 * i - 1], pts[2 * i], 3, rgb) end
end

--- Draw with a painter (util/lovepaint.lua on screen, util/probe.lua for the probes).
---@param state table @param P table
function M.paint(state, P)
  if state.poly then
    local k = 0
    for piece in state.poly:elems() do
      k = k + 1
      P:fill(piece, PALETTE[(k - 1) % #PALETTE + 1], 'piece ' .. k)
      P:outline(piece, PIECE_EDGE)
    end
  end
  if state.outline and #state.outline >= 4 then
    polyline(P, state.outline, state.poly and OUTLINE or REFUSED, true, 2)
  end
  local d = state.draft
  if #d > 0 then
    polyline(P, d, DRAFT, false, 2)
    if state.mouseX then P:line(d[#d - 1], d[#d], state.mouseX, state.mouseY, DRAFT, 1) end
  end
end

--- Draw on screen (LÖVE only).
function M.draw(state) scene.draw(M, state) end

--- Screenshot probes of this state: one inside each convex piece, and background.
---@param state table
---@return table[]
function M.probes(state)
  local labels = {}
  if state.poly then
    for k = 1, state.poly:getShapeCount() do labels[k] = 'piece ' .. k end
  end
  return scene.probes(M, state, labels)
end

return M
