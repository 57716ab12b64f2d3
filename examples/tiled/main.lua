-- A level drawn in Tiled, loaded with strike: level.lua (Tiled's Lua export format) becomes
-- bodies of a space with S.tiled; a character walks it with space:move and picks up the
-- coins, sensors on their own layer, that it touches.
--
--   love examples/tiled        arrows or A, D to walk; Space, Up or W to jump
--
-- (`--frames N` quits after N frames, printing the status line: the repository's checks.)

-- strike is the folder strike/ at the root of this repository. In a game of your own, copy
-- strike/ next to main.lua; `require 'strike'` is then all it takes.
local source = love.filesystem.getSource()
package.path = source .. '/../../?.lua;' .. source .. '/../../?/init.lua;' .. package.path
local S = require('strike')

local GRAVITY, SPEED, JUMP = 1500, 180, 600
local CHARACTER = { slope = math.rad(50), snap = 4, step = 10 }
local COLOURS = { ground = { 0.45, 0.38, 0.3 }, brick = { 0.6, 0.3, 0.25 }, platform = { 0.45, 0.75, 0.9 },
  hill = { 0.4, 0.6, 0.3 }, boulder = { 0.55, 0.55, 0.6 }, coin = { 1, 0.85, 0.25 } }
-- What a query's filter may be: a table naming the layers to keep. The coins are on 'coin'.
local COINS_ONLY = { mask = { 'coin' } }
local found = {} -- the coin query's list, filled again by every query (nothing allocated)

local space, level, player, coins
local frames, quitAfter = 0, nil

-- The name of the Tiled object or tile a body came from: its object's name, or for a region
-- of tiles its first tile's `kind` property (custom properties, set in Tiled).
local function nameOf(body)
  local o = level.objectOf[body]
  if o.tiles then return o.tile.properties.kind end
  return o.name
end

-- A point object named `name` on the layer `layerName`: S.tiled loads only the collidable
-- layers, and the game reads anything else from the map itself.
local function point(map, layerName, name)
  for _, layer in ipairs(map.layers) do
    if layer.name == layerName then
      for _, o in ipairs(layer.objects) do
        if o.name == name then return o.x, o.y end
      end
    end
  end
  error(('the map has no point %q on layer %q'):format(name, layerName))
end

function love.load(args)
  for i, a in ipairs(args or {}) do
    if a == '--frames' then quitAfter = tonumber(args[i + 1]) end
  end
  local map = love.filesystem.load('level.lua')() -- strike reads no files: the game loads the map
  space = S.pace()
  level = S.tiled(map, space)
  coins = { total = 0, picked = 0 }
  for _, body in ipairs(level.bodies) do
    if nameOf(body) == 'coin' then coins.total = coins.total + 1 end
  end
  local x, y = point(map, 'markers', 'spawn')
  -- The character collides with the level's layer only (its mask); the coins are sensors,
  -- which a move passes anyway.
  player = { body = space:add(S.hapes.Capsule(x, y - 22, 20, 44), { layer = 'player', mask = { 'level' } }),
    vy = 0, onGround = false }
end

local function status()
  local x, y = player.body:getCentroid()
  return ('coins %d/%d  x %.0f  y %.0f  %s'):format(coins.picked, coins.total, x, y,
    player.onGround and 'on the ground' or 'in the air')
end

function love.update(dt)
  dt = math.min(dt, 1 / 30)
  local kb = love.keyboard
  local dir = (kb.isDown('right', 'd') and 1 or 0) - (kb.isDown('left', 'a') and 1 or 0)
  player.vy = player.vy + GRAVITY * dt
  local x, y = player.body:getCentroid()
  local _, _, cols, n = space:move(player.body, x + dir * SPEED * dt, y + player.vy * dt, nil, CHARACTER)
  player.onGround = false
  for i = 1, n do
    local c = cols[i]
    if c.ny < -0.7 then
      player.onGround = true
      if player.vy > 0 then player.vy = 0 end
    elseif c.ny > 0.7 and player.vy < 0 then
      player.vy = 0
    end
  end
  -- Pick up the coins the character overlaps: an exact query against its shape.
  local touched, count = space:queryShape(player.body, COINS_ONLY, found)
  for i = 1, count do
    space:remove(touched[i])
    coins.picked = coins.picked + 1
  end
  frames = frames + 1
  if quitAfter and frames >= quitAfter then
    print(status())
    love.event.quit(0)
  end
end

function love.keypressed(key)
  if (key == 'space' or key == 'up' or key == 'w') and player.onGround then player.vy = -JUMP end
end

function love.draw()
  for _, body in ipairs(level.bodies) do
    if space:has(body) then                     -- (a coin picked up has left the space)
      love.graphics.setColor(COLOURS[nameOf(body)])
      body:draw('fill')
    end
  end
  love.graphics.setColor(0.85, 0.45, 0.3)
  player.body:draw('fill')
  love.graphics.setColor(1, 1, 1)
  love.graphics.print(status(), 40, 10)
  love.graphics.print('arrows or A, D: walk    Space, Up or W: jump', 40, 30)
end
