-- A platformer with strike: a character walks and jumps over separate floor tiles, a slope,
-- stairs and a one-way platform, moved by space:move with the character options.
--
--   love examples/platformer          arrows or A, D to walk; Space, Up or W to jump
--
-- (`--frames N` quits after N frames, printing the status line: the repository's checks.)

-- strike is the folder strike/ at the root of this repository. In a game of your own, copy
-- strike/ next to main.lua; `require 'strike'` is then all it takes.
local source = love.filesystem.getSource()
package.path = source .. '/../../?.lua;' .. source .. '/../../?/init.lua;' .. package.path
local S = require('strike')

local GRAVITY = 1500                    -- px/s², down (y grows downward on a LÖVE screen)
local SPEED = 180                       -- px/s
local JUMP = 600                        -- px/s up: a jump 120 px high
-- Walk up slopes up to 50°, stay on the ground going down (snap) and climb steps up to
-- 10 px without jumping (step).
local CHARACTER = { slope = math.rad(50), snap = 4, step = 10 }

local space = S.pace()
local level = {}                        -- the bodies to draw
local player                            -- { body =, vy =, onGround = }
local frames, quitAfter = 0, nil

-- A piece of the level: a body in the space. Each tile is a body of its own: the character
-- slides across the seams between them without catching.
local function solid(body)
  level[#level + 1] = space:add(body)
  return body
end

function love.load(args)
  for i, a in ipairs(args or {}) do
    if a == '--frames' then quitAfter = tonumber(args[i + 1]) end
  end
  for i = 0, 9 do solid(S.hapes.Rectangle(20 + 40 * i, 540, 40, 40)) end         -- floor tiles
  solid(S.hapes.ConvexPolygon(400, 520, 520, 460, 520, 560, 400, 560))             -- a slope, 26.6°
  for i = 0, 6 do                                                                   -- stairs, 8 px a step
    local top = 460 + 8 * i
    solid(S.hapes.Rectangle(540 + 40 * i, (top + 560) / 2, 40, 560 - top))
  end
  solid(S.hapes.Rectangle(-10, 300, 20, 600))                                       -- the window's sides
  solid(S.hapes.Rectangle(810, 300, 20, 600))
  -- A one-way platform: a chain segment given left to right is solid from above only.
  solid(S.trikers.Chain(120, 430, 300, 430))
  -- The character: a capsule 20 wide and 44 tall, its feet on the first tile.
  player = { body = space:add(S.hapes.Capsule(60, 520 - 22, 20, 44)), vy = 0, onGround = false }
end

local function status()
  local x, y = player.body:getCentroid()
  return ('x %.0f  y %.0f  %s'):format(x, y, player.onGround and 'on the ground' or 'in the air')
end

function love.update(dt)
  dt = math.min(dt, 1 / 30)             -- a long frame (a window drag) would jump
  local kb = love.keyboard
  local dir = (kb.isDown('right', 'd') and 1 or 0) - (kb.isDown('left', 'a') and 1 or 0)
  player.vy = player.vy + GRAVITY * dt
  local x, y = player.body:getCentroid()
  -- Move toward the goal; strike sweeps the way there (nothing tunnels) and slides along
  -- what it meets. No filter: everything is solid.
  local _, _, cols, n = space:move(player.body, x + dir * SPEED * dt, y + player.vy * dt, nil, CHARACTER)
  -- The collisions tell where the ground is: a normal pointing up. (After a move the body
  -- stops a hair short of what it met, so S.triking or space:check would see it apart.)
  player.onGround = false
  for i = 1, n do
    local c = cols[i]
    if c.ny < -0.7 then
      player.onGround = true
      if player.vy > 0 then player.vy = 0 end
    elseif c.ny > 0.7 and player.vy < 0 then
      player.vy = 0                     -- a ceiling
    end
  end
  frames = frames + 1
  if quitAfter and frames >= quitAfter then
    print(status())
    love.event.quit(0)
  end
end

function love.keypressed(key)
  if (key == 'space' or key == 'up' or key == 'w') and player.onGround then
    player.vy = -JUMP
  end
end

function love.draw()
  love.graphics.setColor(0.45, 0.38, 0.3)
  for _, body in ipairs(level) do body:draw('fill') end
  love.graphics.setColor(0.85, 0.45, 0.3)
  player.body:draw('fill')
  love.graphics.setColor(1, 1, 1)
  love.graphics.print(status(), 10, 10)
  love.graphics.print('arrows or A, D: walk    Space, Up or W: jump', 10, 30)
end
