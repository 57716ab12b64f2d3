--- A stand-in for LÖVE 11.4, for the specs that run LÖVE code without LÖVE: the code blocks
--- of the README and the guides (spec/docs_examples_spec.lua) and the example games
--- (spec/examples_spec.lua). love.graphics checks each call's arguments as LÖVE would refuse
--- them (a wrong draw mode, a coordinate that is not a finite number, a polygon of fewer
--- than 3 vertices: an error at the caller's line) and records it; love.keyboard and
--- love.mouse answer from what the spec holds down; love.filesystem reads the game's folder
--- with io. A function or module this stand-in does not have is an error naming it, never a
--- silent nil, so code that uses more of LÖVE than it provides fails here, visibly.
---
---   local fake = require('spec.helpers.love').new({ source = 'examples/platformer' })
---   rawset(_G, 'love', fake.love)
---   fake.keys.right = true            -- held down
---   fake.run(60, 1 / 60)              -- love.load once, then 60 x (love.update, love.draw)
---   fake.printed                      -- the texts drawn by the last love.draw
local M = {}

local function finite(v) return type(v) == 'number' and v == v and v > -math.huge and v < math.huge end

-- An error at the line that called love.<fname>: `depth` 1 when fail is called by that
-- function itself, 2 when by a helper it calls.
local function fail(fname, msg, depth)
  error(('love.%s: %s'):format(fname, msg), 2 + (depth or 1))
end

-- A module table whose missing members are an error naming them.
local function strict(name, t)
  return setmetatable(t, { __index = function(_, k)
    error(('the LÖVE stand-in (spec/helpers/love.lua) has no love.%s.%s'):format(name, tostring(k)), 2)
  end })
end

local MODES = { fill = true, line = true }

--- A fresh stand-in. opts.source: the game's folder (what love.filesystem.getSource gives and
--- what love.filesystem reads from; default '.'). Returns a table: `love` (to install as the
--- global), `calls` (every graphics call since the last love.draw started: { name, args... }),
--- `printed` (the texts love.graphics.print and printf drew since then), `keys`, `buttons`
--- and `mouse` (what is held down and where the mouse is), `quit` (set by love.event.quit),
--- and `run(frames, dt)`.
---@param opts table|nil
---@return table
function M.new(opts)
  opts = opts or {}
  local source = opts.source or '.'
  local fake = { calls = {}, printed = {}, keys = {}, buttons = {}, mouse = { x = 0, y = 0 }, quit = false }
  local colour = { 1, 1, 1, 1 }
  local lineWidth = 1
  local stack = 0

  local function record(name, ...)
    fake.calls[#fake.calls + 1] = { name, ... }
  end
  -- The coordinates of a draw call: a list of numbers, or one table of them.
  local function coords(fname, ...)
    local list = { ... }
    if type(list[1]) == 'table' then list = list[1] end
    for i, v in ipairs(list) do
      if not finite(v) then fail(fname, ('coordinate %d must be a finite number, got %s'):format(i, tostring(v)), 2) end
    end
    return list
  end
  local function mode(fname, m)
    if not MODES[m] then fail(fname, ("draw mode must be 'fill' or 'line', got %s"):format(tostring(m)), 2) end
  end
  local function numbers(fname, names, ...)
    local args = { ... }
    for i, n in ipairs(names) do
      if not finite(args[i]) then
        fail(fname, ('%s must be a finite number, got %s'):format(n, tostring(args[i])), 2)
      end
    end
  end

  local graphics = {}
  function graphics.setColor(r, g, b, a)
    if type(r) == 'table' then r, g, b, a = r[1], r[2], r[3], r[4] end
    numbers('graphics.setColor', { 'red', 'green', 'blue' }, r, g, b)
    if a ~= nil then numbers('graphics.setColor', { 'alpha' }, a) end
    colour = { r, g, b, a or 1 }
  end
  function graphics.getColor() return colour[1], colour[2], colour[3], colour[4] end
  function graphics.setBackgroundColor(r, g, b)
    if type(r) == 'table' then r, g, b = r[1], r[2], r[3] end
    numbers('graphics.setBackgroundColor', { 'red', 'green', 'blue' }, r, g, b)
  end
  function graphics.clear() record('clear') end
  function graphics.setLineWidth(w)
    numbers('graphics.setLineWidth', { 'width' }, w)
    lineWidth = w
  end
  function graphics.getLineWidth() return lineWidth end
  function graphics.rectangle(m, x, y, w, h, ...)
    mode('graphics.rectangle', m)
    numbers('graphics.rectangle', { 'x', 'y', 'width', 'height' }, x, y, w, h)
    record('rectangle', m, x, y, w, h, ...)
  end
  function graphics.circle(m, x, y, r, ...)
    mode('graphics.circle', m)
    numbers('graphics.circle', { 'x', 'y', 'radius' }, x, y, r)
    record('circle', m, x, y, r, ...)
  end
  function graphics.arc(m, kind, ...)
    mode('graphics.arc', m)
    local args = { ... }
    if type(kind) == 'number' then table.insert(args, 1, kind) end
    numbers('graphics.arc', { 'x', 'y', 'radius', 'angle1', 'angle2' }, args[1], args[2], args[3], args[4], args[5])
    record('arc', m, kind, ...)
  end
  function graphics.polygon(m, ...)
    mode('graphics.polygon', m)
    local v = coords('graphics.polygon', ...)
    if #v < 6 or #v % 2 ~= 0 then
      fail('graphics.polygon', ('needs at least 3 vertices, as pairs of numbers, got %d numbers'):format(#v))
    end
    record('polygon', m, v)
  end
  function graphics.line(...)
    local v = coords('graphics.line', ...)
    if #v < 4 or #v % 2 ~= 0 then
      fail('graphics.line', ('needs at least 2 vertices, as pairs of numbers, got %d numbers'):format(#v))
    end
    record('line', v)
  end
  function graphics.points(...)
    local v = coords('graphics.points', ...)
    if #v % 2 ~= 0 then fail('graphics.points', 'needs pairs of numbers') end
    record('points', v)
  end
  local function text(fname, s)
    if type(s) ~= 'string' and type(s) ~= 'number' then
      fail(fname, ('text must be a string or a number, got %s'):format(type(s)), 2)
    end
    return tostring(s)
  end
  function graphics.print(s, x, y)
    local t = text('graphics.print', s)
    numbers('graphics.print', { 'x', 'y' }, x or 0, y or 0)
    fake.printed[#fake.printed + 1] = t
    record('print', t, x, y)
  end
  function graphics.printf(s, x, y, limit, align)
    local t = text('graphics.printf', s)
    numbers('graphics.printf', { 'x', 'y', 'limit' }, x, y, limit)
    if align ~= nil and align ~= 'left' and align ~= 'right' and align ~= 'center' and align ~= 'justify' then
      fail('graphics.printf', 'bad alignment ' .. tostring(align))
    end
    fake.printed[#fake.printed + 1] = t
    record('printf', t, x, y, limit, align)
  end
  function graphics.push() stack = stack + 1 end
  function graphics.pop()
    if stack == 0 then fail('graphics.pop', 'no push to pop') end
    stack = stack - 1
  end
  function graphics.origin() end
  function graphics.translate(x, y) numbers('graphics.translate', { 'x', 'y' }, x, y) end
  function graphics.scale(sx, sy) numbers('graphics.scale', { 'sx', 'sy' }, sx, sy or sx) end
  function graphics.rotate(a) numbers('graphics.rotate', { 'angle' }, a) end
  function graphics.getWidth() return 800 end
  function graphics.getHeight() return 600 end
  function graphics.getDimensions() return 800, 600 end

  local keyboard = {}
  function keyboard.isDown(...)
    for _, k in ipairs({ ... }) do
      if type(k) ~= 'string' then fail('keyboard.isDown', 'keys must be strings') end
      if fake.keys[k] then return true end
    end
    return false
  end
  function keyboard.setKeyRepeat() end

  local mouse = {}
  function mouse.getPosition() return fake.mouse.x, fake.mouse.y end
  function mouse.getX() return fake.mouse.x end
  function mouse.getY() return fake.mouse.y end
  function mouse.isDown(...)
    for _, b in ipairs({ ... }) do
      if fake.buttons[b] then return true end
    end
    return false
  end

  local filesystem = {}
  function filesystem.getSource() return source end
  function filesystem.load(name)
    if type(name) ~= 'string' then fail('filesystem.load', 'the file name must be a string') end
    return loadfile(source .. '/' .. name)
  end
  function filesystem.read(name)
    local f, err = io.open(source .. '/' .. name, 'rb')
    if not f then return nil, err end
    local s = f:read('*a')
    f:close()
    return s, #s
  end

  local timer = {}
  local now = 0
  function timer.getTime() return now end
  function timer.getFPS() return 60 end

  local event = {}
  function event.quit() fake.quit = true end

  local window = {}
  function window.setTitle() end
  function window.getMode() return 800, 600, {} end

  fake.love = {
    graphics = strict('graphics', graphics), keyboard = strict('keyboard', keyboard),
    mouse = strict('mouse', mouse), filesystem = strict('filesystem', filesystem),
    timer = strict('timer', timer), event = strict('event', event), window = strict('window', window),
  }
  -- A callback the game did not define reads as nil; any other name is a module this stand-in
  -- lacks: an error naming it.
  local CALLBACKS = { load = true, update = true, draw = true, keypressed = true, keyreleased = true,
    mousepressed = true, mousereleased = true, mousemoved = true, wheelmoved = true, textinput = true,
    resize = true, quit = true, focus = true, conf = true, errorhandler = true }
  setmetatable(fake.love, { __index = function(_, k)
    if CALLBACKS[k] then return nil end
    error(('the LÖVE stand-in (spec/helpers/love.lua) has no love.%s'):format(tostring(k)), 2)
  end })

  --- Draw one frame: love.draw with the records of the last frame cleared first.
  function fake.draw()
    fake.calls, fake.printed = {}, {}
    if rawget(fake.love, 'draw') then fake.love.draw() end
    if stack ~= 0 then error(('love.draw left %d graphics.push without its pop'):format(stack), 2) end
  end

  --- love.load (once, with `args`), then `frames` times love.update(dt) and love.draw.
  ---@param frames integer @param dt number|nil default 1/60 @param args table|nil
  function fake.run(frames, dt, args)
    dt = dt or 1 / 60
    if not fake.loaded then
      fake.loaded = true
      if rawget(fake.love, 'load') then fake.love.load(args or {}) end
    end
    for _ = 1, frames do
      now = now + dt
      if rawget(fake.love, 'update') then fake.love.update(dt) end
      fake.draw()
    end
  end

  --- A key pressed (held from now on) and its love.keypressed; `release` lets it go.
  ---@param key string
  function fake.press(key)
    fake.keys[key] = true
    if rawget(fake.love, 'keypressed') then fake.love.keypressed(key, key, false) end
  end
  ---@param key string
  function fake.release(key)
    fake.keys[key] = nil
    if rawget(fake.love, 'keyreleased') then fake.love.keyreleased(key, key) end
  end

  return fake
end

return M
