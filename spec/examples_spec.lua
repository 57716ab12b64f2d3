-- The example games (examples/platformer, examples/shooter, examples/tiled), run headless:
-- each main.lua under a stand-in for LÖVE (spec/helpers/love.lua, which checks every draw
-- call's arguments), its love.load, love.update and love.draw driven frame by frame with
-- keys and the mouse held as a player would, and what it does read from the status line it
-- draws, as a player reads it. The expected places come from each level's geometry (given
-- beside each check), not from a run. tools/love-check.sh also runs each one under LÖVE.
local lovestub = require('spec.helpers.love')

-- A fresh game: examples/<name>/main.lua loaded with a new stand-in as `love`.
local function game(name)
  local fake = lovestub.new({ source = 'examples/' .. name })
  local path = package.path
  rawset(_G, 'love', fake.love)
  finally(function()
    rawset(_G, 'love', nil)
    package.path = path -- (main.lua puts the repository's root on it)
  end)
  dofile('examples/' .. name .. '/main.lua')
  return fake
end

-- The status line the last frame drew (the first text it printed).
local function status(fake)
  assert.is_true(#fake.printed > 0, 'the frame drew no text')
  return fake.printed[1]
end

-- The whole numbers after each label of a status line: `x 60  y 498` -> {x = 60, y = 498}.
local function numbers(line)
  local t = {}
  for label, v in line:gmatch('(%a+) (%-?%d+)') do t[label] = tonumber(v) end
  return t
end

-- Run frames while keys are held, then let them go.
local function hold(fake, keys, frames)
  for _, k in ipairs(keys) do fake.keys[k] = true end
  fake.run(frames)
  for _, k in ipairs(keys) do fake.keys[k] = nil end
end

local function tap(fake, key)
  fake.press(key)
  fake.release(key)
end

describe('examples/platformer', function()
  it('stands on the tiles, walks, jumps up through the one-way platform onto it, climbs stairs', function()
    local fake = game('platformer')
    fake.run(30)
    -- a capsule 44 tall on tiles whose top is y = 520: its centre at 498
    assert.equals('x 60  y 498  on the ground', status(fake))
    hold(fake, { 'right' }, 60) -- 1 s at 180 px/s
    assert.equals('x 240  y 498  on the ground', status(fake))
    -- under the platform (x 120 to 300, y 430): a jump 120 px high goes up through it from
    -- below and lands on top (centre 430 - 22)
    tap(fake, 'space')
    fake.run(1)
    assert.matches('in the air', status(fake))
    fake.run(59)
    assert.equals('x 240  y 408  on the ground', status(fake))
    -- off the platform, up the slope and down the stairs to the right wall (its face at x =
    -- 800, the capsule 20 wide), on the last step (top 460 + 6 * 8 = 508)
    hold(fake, { 'right' }, 200)
    assert.equals('x 790  y 486  on the ground', status(fake))
    -- back: up the 8 px steps without jumping (step = 10), down the slope, to the left wall
    hold(fake, { 'left' }, 400)
    assert.equals('x 10  y 498  on the ground', status(fake))
  end)

  it('climbs the 8 px stairs without leaving the ground (the step option)', function()
    -- from the right wall, walking left: the stairs go up by 8 px a step, which the step
    -- option (10 px) climbs: up, across and down onto the step, never in the air
    local fake = game('platformer')
    fake.run(10)
    hold(fake, { 'right' }, 260)
    assert.equals('x 790  y 486  on the ground', status(fake))
    fake.keys.left = true
    for _ = 1, 100 do
      fake.run(1)
      assert.matches('on the ground', status(fake))
    end
  end)
end)

describe('examples/shooter', function()
  -- the arena's walls are 16 px thick along the window's edges (800 x 600); bullets are
  -- circles of radius 3 drawn where they are
  local function bulletsDrawn(fake)
    local list = {}
    for _, c in ipairs(fake.calls) do
      if c[1] == 'circle' and c[5] == 3 then list[#list + 1] = { x = c[3], y = c[4] } end
    end
    return list
  end

  it('starts with full health and spawns an enemy', function()
    local fake = game('shooter')
    fake.run(30)
    assert.equals('health 5  score 0  enemies 1  bullets 0', status(fake))
  end)

  it('shoots the enemy that comes at the player from its spawn point', function()
    local fake = game('shooter')
    fake.run(1)
    -- the first enemy spawns at (60, 60) and walks straight at the player (400, 300): aimed
    -- at its spawn point, every bullet goes along its way; 3 hits each
    fake.mouse.x, fake.mouse.y = 60, 60
    fake.buttons[1] = true
    fake.run(90)
    local s = numbers(status(fake))
    assert.is_true(s.score >= 1, status(fake))
    assert.equals(5, s.health)
  end)

  it('never lets a bullet through a wall, at 25 px a frame against 16 px walls', function()
    local fake = game('shooter')
    fake.run(1)
    -- straight up at the top wall (y 0 to 16), walking down meanwhile, so that the bullets
    -- start from every height: a bullet checked only where each frame puts it would pass the
    -- wall from some of them (25 px a frame against the 22 px where it overlaps the wall)
    fake.mouse.x, fake.mouse.y = 400, 0
    fake.keys.space, fake.keys.down = true, true
    local seen = 0
    for _ = 1, 120 do
      fake.run(1)
      for _, b in ipairs(bulletsDrawn(fake)) do
        seen = seen + 1
        assert.is_true(b.y >= 16 + 3 - 1e-3, ('a bullet drawn at y = %s, in or past the wall'):format(b.y))
      end
      assert.is_true(numbers(status(fake)).bullets <= 3, status(fake))
    end
    assert.is_true(seen >= 60, ('%d bullets drawn'):format(seen))
  end)

  it('loses health to enemies that reach the player, ends, and starts again on R', function()
    local fake = game('shooter')
    local health = 5
    for _ = 1, 40 * 60 do
      fake.run(1)
      local s = status(fake)
      if s:match('^game over') then break end
      local h = numbers(s).health
      assert.is_true(h <= health, s)
      health = h
    end
    assert.matches('^game over: score 0', status(fake))
    tap(fake, 'r')
    fake.run(1)
    assert.equals('health 5  score 0  enemies 1  bullets 0', status(fake))
  end)
end)

describe('examples/tiled', function()
  it('loads the map, walks it, picks up every coin, jumps onto the one-way platform', function()
    local fake = game('tiled')
    fake.run(30)
    -- the spawn point (200, 480) on the ground, whose top is row 15: y = 480
    assert.equals('coins 0/5  x 200  y 458  on the ground', status(fake))
    -- right: the coin on the floor, over the hill (its top at 416) and its two coins, to the
    -- boulder (a circle of radius 24 at 728, 456), which stops it
    hold(fake, { 'right' }, 300)
    local s = numbers(status(fake))
    assert.equals(3, s.coins)
    assert.is_true(s.x > 680 and s.x < 704, status(fake))
    assert.equals(458, s.y)
    -- left: back over the hill, the coin left of the spawn point, to the wall (bricks of
    -- column 0: its face at x = 32)
    hold(fake, { 'left' }, 400)
    assert.equals('coins 4/5  x 42  y 458  on the ground', status(fake))
    -- under the platform (x 96 to 256, y 384) a jump goes up through it, takes the coin
    -- there and lands on top
    hold(fake, { 'right' }, 50)
    tap(fake, 'space')
    fake.run(60)
    assert.equals('coins 5/5  x 192  y 362  on the ground', status(fake))
  end)
end)

describe('the examples under LÖVE', function()
  for _, name in ipairs({ 'platformer', 'shooter', 'tiled' }) do
    it(name .. ': --frames N quits after N frames, printing the status line', function()
      local fake = game(name)
      local printed = {}
      local print = _G.print
      _G.print = function(s) printed[#printed + 1] = s end
      finally(function() _G.print = print end)
      fake.run(3, 1 / 60, { '--frames', '3' })
      _G.print = print
      assert.is_true(fake.quit)
      assert.equals(1, #printed)
      assert.equals(status(fake), printed[1])
    end)
  end
end)
