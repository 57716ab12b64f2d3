-- A top-down shooter with strike: walk an arena, shoot the enemies that chase you. Bullets
-- are fast (25 px a frame, more than a wall is thick) and never pass a wall: space:move
-- sweeps them. Enemies chase you only when they can see you: a ray from each enemy's centre,
-- with a filter, since a ray that starts inside a body hits that body.
--
--   love examples/shooter     arrows or W, A, S, D to walk; aim with the mouse; hold the
--                             left button or Space to fire; R to start again
--
-- (`--frames N` quits after N frames, printing the status line: the repository's checks.)

-- strike is the folder strike/ at the root of this repository. In a game of your own, copy
-- strike/ next to main.lua; `require 'strike'` is then all it takes.
local source = love.filesystem.getSource()
package.path = source .. '/../../?.lua;' .. source .. '/../../?/init.lua;' .. package.path
local S = require('strike')

local W, H, WALL = 800, 600, 16          -- the arena: the window, walls 16 px thick
local PLAYER_SPEED, ENEMY_SPEED = 220, 90 -- px/s
local BULLET_SPEED, BULLET_R = 1500, 3  -- px/s (25 px a frame at 60 frames a second), px
local FIRE_EVERY = 0.1                  -- s between shots
local SPAWN_EVERY, MAX_ENEMIES = 1.2, 8
local SPAWNS = { { 60, 60 }, { 740, 60 }, { 740, 540 }, { 60, 540 } }

local space, player, walls, enemies, bullets, game
local frames, quitAfter = 0, nil

-- Your own data goes on the bodies: any name that does not start with `_` and is not a
-- method's (`role`, `hp` here). strike never reads or writes them.
local function wall(body)
  body.role = 'wall'
  walls[#walls + 1] = space:add(body)
end

local function start()
  space = S.pace()
  walls, enemies, bullets = {}, {}, {}
  game = { health = 5, hurtFor = 0, score = 0, reload = 0, spawnIn = 0, spawned = 0, over = false }
  wall(S.hapes.Rectangle(W / 2, WALL / 2, W, WALL))
  wall(S.hapes.Rectangle(W / 2, H - WALL / 2, W, WALL))
  wall(S.hapes.Rectangle(WALL / 2, H / 2, WALL, H))
  wall(S.hapes.Rectangle(W - WALL / 2, H / 2, WALL, H))
  wall(S.hapes.Rectangle(300, 130, 120, 16, 0.3))                -- pillars to hide behind
  wall(S.hapes.Rectangle(560, 460, 16, 100))
  wall(S.hapes.Circle(640, 300, 30))
  wall(S.hapes.RegularPolygon(200, 380, 6, 36))
  player = space:add(S.hapes.Circle(W / 2, H / 2, 12))
  player.role = 'player'
end

function love.load(args)
  for i, a in ipairs(args or {}) do
    if a == '--frames' then quitAfter = tonumber(args[i + 1]) end
  end
  start()
end

-- space:move's filters: what each kind of body does to what it meets. 'slide' goes on along
-- the surface, 'touch' stops there, 'cross' goes through and reports it; nil goes through.
local function playerFilter(_, other)
  if other.role == 'wall' then return 'slide' end
  if other.role == 'enemy' then return 'cross' end -- it hurts (below)
end
local function enemyFilter(_, other)
  if other.role == 'wall' or other.role == 'enemy' then return 'slide' end
  if other.role == 'player' then return 'touch' end
end
local function bulletFilter(_, other)
  if other.role == 'wall' or other.role == 'enemy' then return 'touch' end
end
-- Only walls block the view. Without a filter, an enemy's ray from its own centre would hit
-- the enemy itself, where the ray leaves it.
local function onlyWalls(body) return body.role == 'wall' end

local function hurt()
  if game.hurtFor <= 0 then
    game.health, game.hurtFor = game.health - 1, 1 -- then a second without harm
    if game.health <= 0 then game.over = true end
  end
end

local function fire(px, py)
  local mx, my = love.mouse.getPosition()
  local dx, dy = mx - px, my - py
  local len = math.sqrt(dx * dx + dy * dy)
  if len < 1 then return end
  local b = space:add(S.hapes.Circle(px + dx / len * 16, py + dy / len * 16, BULLET_R))
  b.role = 'bullet'
  bullets[#bullets + 1] = { body = b, vx = dx / len * BULLET_SPEED, vy = dy / len * BULLET_SPEED, life = 2 }
end

local function status()
  if game.over then return ('game over: score %d    R to start again'):format(game.score) end
  return ('health %d  score %d  enemies %d  bullets %d'):format(game.health, game.score, #enemies, #bullets)
end

local function updateGame(dt)
  local kb = love.keyboard
  local px, py = player:getCentroid()
  -- the player
  local dx = (kb.isDown('right', 'd') and 1 or 0) - (kb.isDown('left', 'a') and 1 or 0)
  local dy = (kb.isDown('down', 's') and 1 or 0) - (kb.isDown('up', 'w') and 1 or 0)
  local speed = PLAYER_SPEED * ((dx ~= 0 and dy ~= 0) and math.sqrt(0.5) or 1)
  local _, _, cols, n = space:move(player, px + dx * speed * dt, py + dy * speed * dt, playerFilter)
  for i = 1, n do
    if cols[i].other.role == 'enemy' then hurt() end
  end
  px, py = player:getCentroid()
  -- firing
  game.reload = game.reload - dt
  if (love.mouse.isDown(1) or kb.isDown('space')) and game.reload <= 0 then
    fire(px, py)
    game.reload = FIRE_EVERY
  end
  -- new enemies, at the spawn points in turn
  game.spawnIn = game.spawnIn - dt
  if game.spawnIn <= 0 and #enemies < MAX_ENEMIES then
    local at = SPAWNS[game.spawned % #SPAWNS + 1]
    local e = space:add(S.hapes.Circle(at[1], at[2], 14))
    e.role, e.hp = 'enemy', 3
    enemies[#enemies + 1] = e
    game.spawned, game.spawnIn = game.spawned + 1, SPAWN_EVERY
  end
  -- enemies: walk toward the player when they see it
  for _, e in ipairs(enemies) do
    local ex, ey = e:getCentroid()
    local tx, ty = px - ex, py - ey
    local dist = math.sqrt(tx * tx + ty * ty)
    if dist > 0 and not space:rayCast(ex, ey, tx, ty, dist, onlyWalls) then
      local step = ENEMY_SPEED * dt / dist
      local _, _, ecols, en = space:move(e, ex + tx * step, ey + ty * step, enemyFilter)
      for i = 1, en do
        if ecols[i].other == player then hurt() end
      end
    end
  end
  -- bullets: each stops at the first wall or enemy its move meets, however fast it goes
  for i = #bullets, 1, -1 do
    local b = bullets[i]
    local bx, by = b.body:getCentroid()
    local _, _, bcols, bn = space:move(b.body, bx + b.vx * dt, by + b.vy * dt, bulletFilter)
    b.life = b.life - dt
    if bn > 0 or b.life <= 0 then
      local hit = bn > 0 and bcols[1].other
      if hit and hit.role == 'enemy' then
        hit.hp = hit.hp - 1
        if hit.hp <= 0 then
          space:remove(hit)
          for k = #enemies, 1, -1 do
            if enemies[k] == hit then table.remove(enemies, k) end
          end
          game.score = game.score + 1
        end
      end
      space:remove(b.body)
      table.remove(bullets, i)
    end
  end
  game.hurtFor = game.hurtFor - dt
end

function love.update(dt)
  dt = math.min(dt, 1 / 30)
  if not game.over then updateGame(dt) end
  frames = frames + 1
  if quitAfter and frames >= quitAfter then
    print(status())
    love.event.quit(0)
  end
end

function love.keypressed(key)
  if key == 'r' then start() end
end

function love.draw()
  love.graphics.setColor(0.4, 0.42, 0.5)
  for _, body in ipairs(walls) do body:draw('fill') end
  love.graphics.setColor(0.85, 0.3, 0.3)
  for _, e in ipairs(enemies) do e:draw('fill') end
  love.graphics.setColor(1, 0.9, 0.4)
  for _, b in ipairs(bullets) do
    local x, y = b.body:getCentroid()
    love.graphics.circle('fill', x, y, BULLET_R)
  end
  local flash = game.hurtFor > 0 and math.floor(game.hurtFor * 10) % 2 == 0
  love.graphics.setColor(flash and 1 or 0.4, flash and 1 or 0.8, 1)
  player:draw('fill')
  love.graphics.setColor(1, 1, 1)
  love.graphics.print(status(), 24, 24)
end
