-- Space:move at its edges (issue 20): the open end of a one-way chain (a platform's edge,
-- never a wall), 'cross' through any number of bodies and the cap on the legs that turn a
-- move, and the character options at their numeric boundaries (an `up` of any finite
-- length, slope, snap and step). Hand-worked cases; each rule has a case on its boundary.
local S = require('strike')
local expect = require('spec.helpers.expect')
local alloc = require('spec.helpers.alloc')
local raisesAt, near = expect.raisesAt, expect.near
local H, T = S.hapes, S.trikers
local show = require('strike.check').describe
local sqrt, rad, pi = math.sqrt, math.rad, math.pi

-- The one-way platform of these specs: y = 420 from x = 60 to 200, given left to right, so
-- solid from above on a LÖVE screen (n = (0, -1)). `side` 1 is its right end (x = 200), -1
-- its left end (x = 60): E is the end's x, and `side` points away from the platform there.
local function platform(side)
  local sp = S.pace()
  local chain = sp:add(T.Chain(60, 420, 200, 420))
  return sp, chain, side == 1 and 200 or 60
end

-- The characters: a box and a capsule 20 wide and 44 tall (the demo's), centred at (x, y).
-- The capsule is a core segment 24 long (y - 12 to y + 12) rounded by 10.
local KINDS = {
  { 'box', function(x, y) return H.Rectangle(x, y, 20, 44) end },
  { 'capsule', function(x, y) return H.Capsule(x, y, 20, 44) end },
}

describe('Space:move past the open end of a one-way chain', function()
  it('passes a body beside the end with a side across the line: sideways, rising and falling', function()
    -- Centred at y = 415 the box spans y [393, 437] and the capsule's straight sides
    -- [403, 427]: both reach 17 below the line, their centroids 5 above it. The near side is
    -- `gap` beyond the end's x: 0 (exactly at it, touching the end), 1 (one unit outside)
    -- or -1 (one unit inside: partly through the platform already). Each moves 15 toward
    -- the platform, and 5 up, 0 or 5 down: every move ends at its goal, meeting nothing.
    -- (The old kernels stopped gaps 0 and 1 at the end, along its outward tangent.)
    for _, side in ipairs({ 1, -1 }) do
      for _, kind in ipairs(KINDS) do
        local name, make = kind[1], kind[2]
        for _, gap in ipairs({ 0, 1, -1 }) do
          for _, dy in ipairs({ -5, 0, 5 }) do
            local sp, _, E = platform(side)
            local x0 = E + side * (10 + gap)
            local body = sp:add(make(x0, 415))
            local what = ('%s, end %d, gap %d, dy %d'):format(name, side, gap, dy)
            local ax, ay, _, n = sp:move(body, x0 - side * 15, 415 + dy)
            assert(n == 0, what .. ': met the end (' .. n .. ' collisions)')
            assert(ax == x0 - side * 15 and ay == 415 + dy, ('%s: stopped at (%.17g, %.17g)'):format(what, ax, ay))
          end
        end
      end
    end
  end)

  it('never pushes a character jumping up past the end sideways; it lands on the platform', function()
    -- The demo's jump (600 px/s up, 1500 px/s^2 down, 1/60 s steps) from the floor beside
    -- the end (centroid 478: below the platform, its feet at 500), drifting toward the
    -- platform at 60 px/s, the near side `gap` beyond the end's x at the start. While it
    -- rises every move reaches its goal (the old kernels held it at the end's x, its side
    -- against the end, at gaps from 5 to 12); it clears the platform and lands on it:
    -- centroid 420 - 22, a skin above, and 60 px nearer (one px a step).
    local opts = { slope = rad(50), snap = 4 }
    for _, side in ipairs({ 1, -1 }) do
      for _, kind in ipairs(KINDS) do
        local name, make = kind[1], kind[2]
        for gap = 0, 14 do
          local sp, chain, E = platform(side)
          local x0 = E + side * (10 + gap)
          local body = sp:add(make(x0, 478))
          local vy = -600
          local landed = false
          for step = 1, 60 do
            vy = vy + 25
            local x, y = body:getCentroid()
            local gx, gy = x - side, y + vy / 60
            local ax, ay, cols, n = sp:move(body, gx, gy, nil, opts)
            if vy < 0 then
              assert(n == 0 and ax == gx and ay == gy, ('%s, end %d, gap %d, step %d: pushed to (%.17g, %.17g)')
                :format(name, side, gap, step, ax, ay))
            end
            for i = 1, n do
              if cols[i].ny < -0.7 then
                vy, landed = 0, landed or cols[i].other == chain
              end
            end
          end
          local x, y = body:getCentroid()
          local what = ('%s, end %d, gap %d'):format(name, side, gap)
          assert(landed, what .. ': never landed on the platform')
          near(x, x0 - side * 60, 1e-9, what .. ': x')
          near(y, 398, 1e-3, what .. ': y')
          assert(y < 398, what .. ': not a skin above the platform')
        end
      end
    end
  end)

  it('passes a rising capsule whose round foot reaches the corner; a level or falling one meets it', function()
    -- The capsule's straight side at the end's x and its core's lower end 1 above the line
    -- (centroid 407, feet at 429). Moving 10 toward the platform its foot meets the end
    -- where the core end is sqrt(99) beyond it: the normal from the end to the core end,
    -- (side * sqrt(99), -1) / 10. Rising by any amount, it passes (a jump); level (dy = 0,
    -- the boundary) or falling it meets the corner from above, as a foot landing on it.
    for _, side in ipairs({ 1, -1 }) do
      for _, dy in ipairs({ -1, -1e-9, 0, 1 }) do
        local sp, chain, E = platform(side)
        local x0 = E + side * 10
        local body = sp:add(H.Capsule(x0, 407, 20, 44))
        local what = ('end %d, dy %g'):format(side, dy)
        local ax, ay, cols, n = sp:move(body, x0 - side * 10, 407 + dy)
        if dy < 0 then
          assert(n == 0 and ax == x0 - side * 10 and ay == 407 + dy, what .. ': met the corner rising')
        else
          assert(n >= 1 and cols[1].other == chain, what .. ': did not meet the corner')
          assert(side * cols[1].nx > 0.9 and cols[1].ny < 0, what .. ': not pushed up and outward')
          if dy == 0 then
            near(cols[1].nx, side * sqrt(99) / 10, 1e-6, what .. ': nx')
            near(cols[1].ny, -0.1, 1e-6, what .. ': ny')
          end
        end
      end
    end
  end)

  it('lands a body falling onto the very end; exactly at the end\'s x or beyond it, it falls past', function()
    -- From feet at y = 400, 40 down. The box one unit inside (its near side over the
    -- platform by 1) lands on it, a skin above: centroid 398 - skin, normal (0, -1); its
    -- near side exactly at the end's x it only grazes the end (touching is not colliding)
    -- and falls past, as one unit outside. The capsule one unit inside comes down on the end
    -- with its round foot, whose core end is 9 beyond it: normal (side * 9, -sqrt(19)) / 10.
    for _, side in ipairs({ 1, -1 }) do
      for _, gap in ipairs({ -1, 0, 1 }) do
        for _, kind in ipairs(KINDS) do
        local name, make = kind[1], kind[2]
          local sp, chain, E = platform(side)
          local x0 = E + side * (10 + gap)
          local body = sp:add(make(x0, 378))
          local what = ('%s, end %d, gap %d'):format(name, side, gap)
          local ax, ay, cols, n = sp:move(body, x0, 418)
          if gap >= 0 then
            assert(n == 0 and ax == x0 and ay == 418, what .. ': met the end')
          elseif name == 'box' then
            assert(n == 1 and cols[1].other == chain, what .. ': did not land')
            near(cols[1].nx, 0, 0, what .. ': nx')
            near(cols[1].ny, -1, 0, what .. ': ny')
            near(ax, x0, 0, what .. ': x')
            assert(cols[1].touchY == ay and ay < 398 and ay > 398 - 1e-3, what .. ': not a skin above')
            assert.is_false(S.triking(body, chain))
          else
            assert(n >= 1 and cols[1].other == chain, what .. ': did not meet the end')
            near(cols[1].nx, side * 0.9, 1e-6, what .. ': nx')
            near(cols[1].ny, -sqrt(19) / 10, 1e-6, what .. ': ny')
          end
        end
      end
    end
  end)

  it('keeps a capsule that landed on the end\'s corner standing there, and walks it onto the platform', function()
    -- Centred 5 beyond the end, the capsule falls onto the corner: normal (side / 2,
    -- -sqrt(3) / 2), 30 degrees from up, walkable with slope = 50 degrees: under gravity it
    -- stays, its centroid 420 - 12 - 10 cos 30 = 399.34, its feet 1.34 below the line (it
    -- reaches behind the line, and still stands on the end). Walking 10 toward the
    -- platform (no gravity), it follows the corner up and over: never partly through.
    for _, side in ipairs({ 1, -1 }) do
      local sp, chain, E = platform(side)
      local x0 = E + side * 5
      local body = sp:add(H.Capsule(x0, 390.5, 20, 44))
      local opts = { slope = rad(50), snap = 4 }
      local vy = 0
      for _ = 1, 40 do
        vy = vy + 25
        local x, y = body:getCentroid()
        local _, _, cols, n = sp:move(body, x, y + vy / 60, nil, opts)
        for i = 1, n do if cols[i].ny < -0.7 then vy = 0 end end
      end
      local x, y = body:getCentroid()
      near(x, x0, 0, 'end ' .. side .. ': x')
      near(y, 420 - 12 - 10 * sqrt(3) / 2, 1e-4, 'end ' .. side .. ': y')
      local _, _, cols, n = sp:move(body, x, y + 0.5, nil, opts)
      assert(n >= 1 and cols[1].other == chain, 'end ' .. side .. ': no longer on the end')
      near(cols[1].nx, side / 2, 1e-6)
      near(cols[1].ny, -sqrt(3) / 2, 1e-6)
      local ax, ay = sp:move(body, x - side * 10, y, nil, opts)
      near(ax, x - side * 10, 1e-9, 'end ' .. side .. ': walked')
      assert(ay + 22 <= 420, ('end %d: its feet at %.17g, below the platform'):format(side, ay + 22))
      assert.is_false(S.triking(body, chain))
    end
  end)

  it('S.weep follows the same rules, either body first', function()
    local chain = T.Chain(60, 420, 200, 420)
    for _, side in ipairs({ 1, -1 }) do
      local E = side == 1 and 200 or 60
      -- a box beside the end, across the line, moving toward the platform: no hit
      local box = H.Rectangle(E + side * 10, 415, 20, 44)
      assert.is_false(S.weep(box, -side * 15, 0, chain))
      assert.is_false(S.weep(chain, side * 15, 0, box))
      assert.is_false(S.weep(H.Capsule(E + side * 10, 415, 20, 44), -side * 15, -3, chain))
      -- landing one unit inside: the box's feet (y = 400) reach the line after 20 of 40
      local lands = H.Rectangle(E + side * 9, 378, 20, 44)
      local h = S.weep(lands, 0, 40, chain)
      assert(h, 'end ' .. side .. ': no landing')
      near(h.t, 0.5, 1e-12)
      near(h.nx, 0, 0)
      near(h.ny, -1, 0)
      h = S.weep(chain, 0, -40, lands)
      assert(h, 'end ' .. side .. ': no landing, chain first')
      near(h.t, 0.5, 1e-12)
      near(h.ny, 1, 0)
      -- the rising capsule's foot: no hit; level: the corner
      local foot = H.Capsule(E + side * 10, 407, 20, 44)
      assert.is_false(S.weep(foot, -side * 10, -1, chain))
      assert.is_false(S.weep(chain, side * 10, 1, foot))
      h = S.weep(foot, -side * 10, 0, chain)
      assert(h, 'end ' .. side .. ': the foot missed the corner')
      near(h.nx, side * sqrt(99) / 10, 1e-6)
      h = S.weep(chain, side * 10, 0, foot)
      assert(h, 'end ' .. side .. ': the foot missed the corner, chain first')
      near(h.nx, -side * sqrt(99) / 10, 1e-6)
    end
  end)

  it('keeps a joint between two segments as it was: a box cannot pass into a convex corner from beside', function()
    -- A platform with a second segment going down at its right end (a convex corner at
    -- x = 200): the joint is no open end. A box beside the joint, across the first
    -- segment's line but in front of the second, moving left into it, meets the second
    -- segment's face (its normal, up and to the right), not nothing.
    local sp = S.pace()
    sp:add(T.Chain(60, 420, 200, 420, 240, 460))
    local box = sp:add(H.Rectangle(215, 418, 10, 10)) -- y [413, 423]; the second segment's line
    -- there is y = 420 + (x - 200): at the box's bottom-left corner (210, 423) it is 430, below
    local _, _, cols, n = sp:move(box, 200, 440)
    assert(n >= 1, 'passed the joint')
    near(cols[1].nx, 1 / sqrt(2), 1e-9)
    near(cols[1].ny, -1 / sqrt(2), 1e-9)
  end)
end)

describe('Space:move and its legs', function()
  -- N walls 1 wide at x = 10 + 2i (i = 1 .. N), 20 tall; a 4 x 4 box from x = 0 to the far
  -- side of the last.
  local function corridor(N)
    local sp = S.pace()
    local walls = {}
    for i = 1, N do walls[i] = sp:add(H.Rectangle(10 + 2 * i, 0, 1, 20)) end
    return sp, walls, sp:add(H.Rectangle(0, 0, 4, 4))
  end
  local function crossing() return 'cross' end

  it('\'cross\' passes through 63, 64, 65 and 300 bodies in one move, each reported in order', function()
    for _, N in ipairs({ 63, 64, 65, 300 }) do
      local sp, walls, box = corridor(N)
      local goal = 20 + 2 * N
      local ax, ay, cols, n = sp:move(box, goal, 0, crossing)
      assert(ax == goal and ay == 0, ('%d bodies: stopped at (%.17g, %.17g)'):format(N, ax, ay))
      assert.equal(N, n)
      local lastT = -1
      for i = 1, N do
        local col = cols[i]
        assert(col.other == walls[i] and col.type == 'cross', ('%d bodies: collision %d out of order'):format(N, i))
        -- the box's right face (x = 2) meets wall i's left face (x = 9.5 + 2i): t = (7.5 + 2i) / goal
        near(col.t, (7.5 + 2 * i) / goal, 1e-12, ('%d bodies: t of %d'):format(N, i))
        assert(col.t > lastT)
        lastT = col.t
      end
      local x = box:getCentroid()
      assert.equal(goal, x)
    end
  end)

  it('passes through bodies with a response of the game\'s that keeps the leg, any number of them', function()
    local sp, walls, box = corridor(300)
    local count = 0
    sp:addResponse('pickup', function(_, _, x, y, gx, gy)
      count = count + 1
      return x, y, gx, gy
    end)
    local ax, _, cols, n = sp:move(box, 620, 0, function() return 'pickup' end)
    assert.equal(620, ax)
    assert.equal(300, n)
    assert.equal(300, count)
    assert.equal(walls[300], cols[300].other)
  end)

  it('crosses 200 bodies, then slides along a wall to where the slide takes it', function()
    -- the walls as above (up to x = 410), then a wall whose left face is x = 500; the box
    -- moves from (0, 0) toward (600, 10): it crosses every wall on the way (its bottom is
    -- at most 8.8 there), meets the far wall when its centroid is at x = 498 (y = 8.3), and
    -- slides down along it to y = 10, a skin short of it
    local sp, walls, box = corridor(200)
    local wall = sp:add(H.Rectangle(510, 0, 20, 200))
    local ax, ay, cols, n = sp:move(box, 600, 10, function(_, other) return other ~= wall and 'cross' or 'slide' end)
    assert.equal(201, n)
    for i = 1, 200 do assert(cols[i].other == walls[i] and cols[i].type == 'cross', 'collision ' .. i) end
    assert(cols[201].other == wall and cols[201].type == 'slide', 'the wall last')
    near(cols[201].t, 498 / 600, 1e-12)
    near(ay, 10, 1e-12)
    assert(ax < 498 and ax > 498 - 1e-3, 'not a skin short of the wall')
    assert.is_false(S.triking(box, wall))
  end)

  -- A corridor between walls x <= 0 and x >= 12 (1,000,000 tall), and a 2 x 2 box at x = 6:
  -- its centroid moves in [1, 11], so a move right by 10 k + 5 and down by 10 k meets a wall
  -- every 10 of its x motion: bouncing, k times (the skin aside).
  local function bounces(k)
    local sp = S.pace()
    local left = sp:add(H.Rectangle(-5, 0, 10, 1e6))
    local right = sp:add(H.Rectangle(17, 0, 10, 1e6))
    local box = sp:add(H.Rectangle(6, 0, 2, 2))
    local x, y, cols, n = sp:move(box, 6 + 10 * k, 10 * k, function() return 'bounce' end)
    return x, y, cols, n, box, left, right
  end

  it('caps the legs that turn a move at 64: the 65th stops there, a skin short of what it met', function()
    -- 64 bounces: the move ends at its goal, (6, 640) (k even: back at x = 6, give or
    -- take a skin per bounce)
    local x, y, _, n = bounces(64)
    assert.equal(64, n)
    near(x, 6, 1e-3)
    near(y, 640, 1e-9)
    -- 65 and more: the 65th bounce is met and reported, and the body stops at its touch:
    -- x = 11 less a skin, y = 645 (the 65th wall met after 645 of the x motion's 650)
    for _, k in ipairs({ 65, 66, 200 }) do
      local bx, by, cols, bn, box, left, right = bounces(k)
      assert.equal(65, bn)
      assert.equal('bounce', cols[65].type)
      assert.equal(right, cols[65].other)
      assert(bx < 11 and bx > 11 - 1e-3, 'not a skin short of the wall')
      near(by, 645, 1e-3)
      assert.is_false(S.triking(box, right))
      assert.is_false(S.triking(box, left))
      assert.equal(bx, (box:getCentroid()))
    end
  end)

  it('does not count the bodies crossed against the cap', function()
    -- 64 bounces and 100 bodies crossed in one move: the goal
    local sp = S.pace()
    sp:add(H.Rectangle(-5, 0, 10, 1e6))
    sp:add(H.Rectangle(17, 0, 10, 1e6))
    local coins = {}
    for i = 1, 100 do coins[sp:add(H.Rectangle(6, 3 + 6 * i, 12, 1))] = true end
    local box = sp:add(H.Rectangle(6, 0, 2, 2))
    local _, y, cols, n = sp:move(box, 646, 640, function(_, other) return coins[other] and 'cross' or 'bounce' end)
    assert.equal(164, n)
    near(y, 640, 1e-9)
    local crossed = 0
    for i = 1, n do if cols[i].type == 'cross' then crossed = crossed + 1 end end
    assert.equal(100, crossed)
  end)
end)

describe('Space:move options at their boundaries', function()
  -- a floor whose top is y = 100 and a 20 x 20 box resting on it (bottom 0.001 above)
  local function world()
    local sp = S.pace()
    sp:add(H.Rectangle(0, 110, 400, 20))
    return sp, sp:add(H.Rectangle(0, 90 - 1e-3, 20, 20))
  end

  -- the results of one move with `opts`: x, y, then each collision's normal
  local function run(opts)
    local sp, box = world()
    local x, y, cols, n = sp:move(box, 10, 95, nil, opts)
    local out = { x, y, n }
    for i = 1, n do out[#out + 1], out[#out + 2] = cols[i].nx, cols[i].ny end
    -- (the space is sound: the box is found where it is)
    local hits = sp:queryPoint(x, y)
    assert(hits[1] == box, 'the box is lost from the space')
    return out
  end

  it('takes an up of any finite length but zero, as its direction', function()
    local slope = rad(50)
    local straight = run({ up = { 0, -1 }, slope = slope, snap = 4 })
    -- squares that underflow (1e-200, the smallest subnormal) and that overflow (1e200, 1e308)
    for _, up in ipairs({ { 0, -1e-200 }, { 0, -5e-324 }, { 0, -1e200 }, { 0, -1.7e308 }, { 0, -3 } }) do
      assert.same(straight, run({ up = up, slope = slope, snap = 4 }))
    end
    local diagonal = run({ up = { 1, -1 }, slope = slope, snap = 4 })
    for _, up in ipairs({ { 1e-200, -1e-200 }, { 5e-324, -5e-324 }, { 1e300, -1e300 }, { 1.5e308, -1.5e308 } }) do
      local got = run({ up = up, slope = slope, snap = 4 })
      assert.equal(#diagonal, #got)
      for i = 1, #got do near(got[i], diagonal[i], 1e-12) end
    end
    -- and a component 1e-308 beside 1e308: the direction is (0, -1) to round-off
    local tiny = run({ up = { 1e-308, -1e308 }, slope = slope, snap = 4 })
    for i = 1, #tiny do near(tiny[i], straight[i], 1e-12) end
  end)

  it('names what is wrong with a bad up', function()
    local sp, box = world()
    local F = 'strike.Space:move: up must be a direction {x, y}'
    local N = F .. ' of two finite numbers, got '
    raisesAt(function() sp:move(box, 1, 1, nil, { up = { 1 / 0, -1 } }) end, N .. '{inf, -1}')
    raisesAt(function() sp:move(box, 1, 1, nil, { up = { 0, -1 / 0 } }) end, N .. '{0, -inf}')
    raisesAt(function() sp:move(box, 1, 1, nil, { up = { 0 / 0, 1 } }) end, N .. '{nan, 1}')
    raisesAt(function() sp:move(box, 1, 1, nil, { up = { 1 } }) end, N .. '{1, nil}')
    raisesAt(function() sp:move(box, 1, 1, nil, { up = { '0', -1 } }) end, N .. '{string "0", -1}')
    raisesAt(function() sp:move(box, 1, 1, nil, { up = { 0, 0 } }) end, F .. ', not {0, 0}')
    raisesAt(function() sp:move(box, 1, 1, nil, { up = { -0.0, 0 } }) end, F .. ', not {0, 0}')
    raisesAt(function() sp:move(box, 1, 1, nil, { up = 'down' }) end, F .. ', got string "down"')
    raisesAt(function() sp:move(box, 1, 1, nil, { up = -1 }) end, F .. ', got -1')
  end)

  it('takes a slope from 0 to just under pi / 2', function()
    local sp, box = world()
    local F = 'strike.Space:move: slope must be an angle in radians from 0 to less than pi / 2, got '
    raisesAt(function() sp:move(box, 1, 1, nil, { slope = pi / 2 }) end, F .. pi / 2)
    raisesAt(function() sp:move(box, 1, 1, nil, { slope = -1e-300 }) end, F .. '-1e-300')
    raisesAt(function() sp:move(box, 1, 1, nil, { slope = 0 / 0 }) end, F .. 'nan')
    raisesAt(function() sp:move(box, 1, 1, nil, { slope = 1 / 0 }) end, F .. 'inf')
    -- the largest double below pi / 2, 0 and a tiny one work; a flat floor is walkable at
    -- each (the box stands: its x motion kept, its y motion dropped)
    local below = pi / 2 - 2 ^ -52
    assert(below < pi / 2)
    for _, slope in ipairs({ below, 0, 1e-300 }) do
      local got = run({ slope = slope })
      near(got[1], 10, 0)
      assert(got[2] < 90 and got[2] > 90 - 1e-3, 'slope ' .. slope .. ': not a skin above the floor')
    end
  end)

  describe('allocation', function()
    setup(alloc.jitOff)
    teardown(alloc.jitOn)

    it('a move with every option allocates nothing (reading them made a table per move)', function()
      local sp, box = world()
      local opts = { up = { 0, -1 }, slope = rad(50), snap = 4, step = 3 }
      local kb = alloc.kbPer(function()
        box:translateTo(0, 89)
        sp:move(box, 10, 95, nil, opts)
      end, 10000)
      alloc.nothingPerCall(kb, 'Space:move with options')
    end)
  end)

  it('takes snap and step heights from 0 to 1e100', function()
    local sp, box = world()
    for _, key in ipairs({ 'snap', 'step' }) do
      local F = 'strike.Space:move: ' .. key .. ' must be a length from 0 to 1e+100, got '
      for _, bad in ipairs({ -1e-300, 1e100 * (1 + 2 ^ -52), 1e300, 1 / 0, 0 / 0 }) do
        raisesAt(function() sp:move(box, 1, 1, nil, { [key] = bad }) end, F .. show(bad))
      end
      raisesAt(function() sp:move(box, 1, 1, nil, { [key] = 'x' }) end, F .. 'string "x"')
      -- 0, the smallest subnormal and 1e100 work (the box still on the floor)
      for _, v in ipairs({ 0, 5e-324, 1e100 }) do
        local got = run({ [key] = v })
        near(got[1], 10, 0)
        assert(got[2] < 90 and got[2] > 89.99, key .. ' ' .. v .. ': y ' .. got[2])
      end
    end
  end)
end)
