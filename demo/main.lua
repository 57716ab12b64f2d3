--- strike's interactive demo, for LÖVE 11.4. From the repository root:
---
---   love demo                      interactive: keys 1-6 switch scenes, H or F1 toggles the
---                                  help, Escape quits
---   love demo --scene N            start with scene N
---   love demo --frames N           quit by itself (exit code 0) after N frames, printing the
---                                  scene's status lines (smoke tests, timings)
---   love demo --screenshot out.png --scene N
---                                  draw scene N's scripted frame (the state its `new`
---                                  returns, then the scene's SHOT_FRAMES updates of 1/60 s
---                                  if it has any: util/scene.lua, advance; help shown) to an
---                                  800x600 canvas, write it as a PNG to out.png (a relative
---                                  path is relative to the current directory), print the
---                                  status lines and quit with exit code 0; on any error, a
---                                  message on stderr and exit code 1
---
--- Unknown arguments are ignored. The scenes live in scenes/ (one module each, listed in
--- scenes/list.lua) and build their state without LÖVE, so the specs can test them in
--- plain Lua; this file only routes LÖVE's callbacks to the current scene and draws the
--- help and status overlays.

-- The game folder is demo/; the library is strike/ beside it, at the repository root.
local source = love.filesystem.getSource()
package.path = source .. '/../?.lua;' .. source .. '/../?/init.lua;' .. package.path

local S = require('strike')
local layout = require('util.layout')
local sceneUtil = require('util.scene')
local scenes = require('scenes.list')

local W, H = layout.WIDTH, layout.HEIGHT

local current = { index = 1, scene = nil, state = nil }
local showHelp = true
local quitting = false
local frameLimit, frames = nil, 0
local shotFrame = nil -- in --screenshot mode, the number of the frame drawn (no FPS to show)

local function setColour(rgb) love.graphics.setColor(rgb[1] / 255, rgb[2] / 255, rgb[3] / 255, 1) end

-- Build scene i's initial state and make it current.
local function switch(i)
  local scene = scenes[i]
  current.index, current.scene = i, scene
  current.state = scene.new(S, W, H)
  -- The stress scene times its collision work; LÖVE's clock is finer than os.clock.
  current.state.clock = love.timer.getTime
end

local function drawHelp()
  local x, y, w, h = layout.helpRect(current.scene)
  setColour(layout.PANEL)
  love.graphics.rectangle('fill', x, y, w, h)
  love.graphics.setScissor(x, y, w, h) -- nothing of the text outside the panel, ever
  for i, line in ipairs(layout.helpLines(scenes, current.index)) do
    setColour(i == 1 and layout.TITLE or layout.TEXT)
    love.graphics.print(line, x + 6, y + 5 + (i - 1) * layout.LINE_HEIGHT)
  end
  love.graphics.setScissor()
end

local function drawStatus()
  local x, y, w, h = layout.statusRect(W, H)
  setColour(layout.PANEL)
  love.graphics.rectangle('fill', x, y, w, h)
  love.graphics.setScissor(x, y, w, h)
  local lines = current.scene.status and current.scene.status(current.state) or {}
  for i = 1, math.min(#lines, layout.STATUS_LINES) do
    local line = lines[i]
    local isError = type(line) == 'table' and line.error
    setColour(isError and layout.ERROR or layout.TEXT)
    love.graphics.print(type(line) == 'table' and line.text or line, x + 8, y + 5 + (i - 1) * layout.LINE_HEIGHT)
  end
  setColour(layout.TEXT)
  local corner = shotFrame and ('frame %d'):format(shotFrame) or ('FPS %d'):format(love.timer.getFPS())
  love.graphics.printf(corner, x, y + 5, w - 8, 'right')
  love.graphics.setScissor()
end

-- One frame: the scene, then the overlays on top.
local function drawFrame()
  local bg = layout.BACKGROUND
  love.graphics.clear(bg[1] / 255, bg[2] / 255, bg[3] / 255, 1)
  love.graphics.setLineWidth(1)
  current.scene.draw(current.state)
  drawStatus()
  if showHelp then drawHelp() end
  love.graphics.setColor(1, 1, 1, 1)
end

local function fail(message)
  io.stderr:write('strike demo: ', message, '\n')
  quitting = true
  love.event.quit(1)
end

-- Options from the game's arguments ("--name value" pairs; anything else is ignored).
local function parseArgs(args)
  local opts = {}
  local i = 1
  while i <= #args do
    local a = args[i]
    if a == '--screenshot' or a == '--scene' or a == '--frames' then
      local v = args[i + 1]
      if v == nil or v:sub(1, 2) == '--' then return nil, a .. ' needs a value' end
      opts[a:sub(3)] = v
      i = i + 2
    else
      i = i + 1
    end
  end
  local n = tonumber(opts.scene or '1')
  if not n or n ~= math.floor(n) or n < 1 or n > #scenes then
    return nil, ('--scene must be a scene number from 1 to %d, got %s'):format(#scenes, tostring(opts.scene))
  end
  opts.scene = n
  if opts.frames then
    local f = tonumber(opts.frames)
    if not f or f ~= math.floor(f) or f < 1 then
      return nil, '--frames must be a whole number > 0, got ' .. opts.frames
    end
    opts.frames = f
  end
  return opts
end

-- Draw scene n's scripted frame to a canvas and write it as a PNG file.
local function screenshot(path, n)
  switch(n)
  sceneUtil.advance(current.scene, current.state)
  shotFrame = current.scene.SHOT_FRAMES or 0
  local canvas = love.graphics.newCanvas(W, H)
  love.graphics.setCanvas(canvas)
  drawFrame()
  love.graphics.setCanvas()
  local png = canvas:newImageData():encode('png'):getString()
  local f, err = io.open(path, 'wb')
  if not f then error('cannot write the screenshot: ' .. tostring(err), 0) end
  local ok, werr = f:write(png)
  local closed, cerr = f:close()
  if not ok or not closed then error('cannot write ' .. path .. ': ' .. tostring(werr or cerr), 0) end
  local lines = current.scene.status and current.scene.status(current.state) or {}
  for _, line in ipairs(lines) do print(type(line) == 'table' and line.text or line) end
  print(('strike demo: scene %d (%s), frame %d, written to %s'):format(n, scenes[n].name, shotFrame, path))
end

-- love.load receives the game's arguments already parsed by love.arg.parseGameArguments
-- (the game folder removed): do not parse them a second time, that drops the first one.
function love.load(args)
  local opts, err = parseArgs(args or {})
  if not opts then return fail(err) end
  if opts.screenshot then
    local ok, e = pcall(screenshot, opts.screenshot, opts.scene)
    if not ok then return fail(tostring(e)) end
    quitting = true
    love.event.quit(0)
    return
  end
  frameLimit = opts.frames
  love.keyboard.setKeyRepeat(false)
  switch(opts.scene)
end

function love.update(dt)
  if quitting then return end
  -- A long frame (a window drag, a breakpoint) would make the scenes jump.
  local scene = current.scene
  if scene.update then scene.update(current.state, math.min(dt, 1 / 20)) end
  frames = frames + 1
  if frameLimit and frames >= frameLimit then
    -- a smoke test's record: where the scene got to
    local lines = scene.status and scene.status(current.state) or {}
    for _, line in ipairs(lines) do print(type(line) == 'table' and line.text or line) end
    print(('strike demo: %d frames of scene %d (%s), %.0f FPS'):format(frames, current.index, scene.name,
      love.timer.getFPS()))
    quitting = true
    love.event.quit(0)
  end
end

function love.draw()
  if quitting or not current.scene then return end
  drawFrame()
end

-- Input: a few keys are global, everything else goes to the scene's handlers (if any).
local function forward(name, ...)
  local handler = current.scene and current.scene[name]
  if handler and not quitting then handler(current.state, ...) end
end

function love.keypressed(key)
  if key == 'escape' then
    quitting = true
    love.event.quit(0)
  elseif key == 'h' or key == 'f1' then
    showHelp = not showHelp
  else
    local n = tonumber(key:match('^kp(%d)$') or key:match('^(%d)$') or '')
    if n and scenes[n] then
      switch(n)
    else
      forward('keypressed', key)
    end
  end
end

function love.keyreleased(key) forward('keyreleased', key) end
function love.mousepressed(x, y, button) forward('mousepressed', x, y, button) end
function love.mousereleased(x, y, button) forward('mousereleased', x, y, button) end
function love.mousemoved(x, y, dx, dy) forward('mousemoved', x, y, dx, dy) end
function love.wheelmoved(dx, dy) forward('wheelmoved', dx, dy) end
