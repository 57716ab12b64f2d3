--- The demo's scenes, in the order of their number keys (1, 2, ...). Pure Lua: each scene
--- module builds its state without LÖVE (see demo/main.lua for how they are driven).
---
--- A scene module is a table with:
---   name, help             its title and its help lines (short: they share a 420-px panel)
---   new(S, w, h)           its initial state, from strike and the window size; plain Lua,
---                          deterministic (seeded randomness only)
---   update(state, dt)      advance by dt seconds (plain Lua)
---   paint(state, P)        draw with painter P (util/lovepaint.lua or util/probe.lua)
---   draw(state)            draw on screen (LÖVE)
---   status(state)          up to two lines for the status bar (a line may be
---                          { text =, error = true })
---   probes(state)          screenshot probes: { x =, y =, r =, g =, b =, what = } points
---                          whose colour the screenshot of this state must show
---   SHOT_FRAMES            (optional) the scripted screenshot shows the state after this
---                          many updates of 1/60 s (util/scene.lua, advance); default 0,
---                          the initial state
---   keypressed, keyreleased, mousepressed, mousereleased, mousemoved, wheelmoved
---                          (optional) LÖVE's arguments, after the state
---
--- util/scene.lua has what the scenes share: draw, the R reset, keyreleased for held keys
--- and the probes' common part.
local ROOT = (...):match('^(.-)[^%.]+$')

return {
  require(ROOT .. 'pairs'),
  require(ROOT .. 'rays'),
  require(ROOT .. 'concave'),
  require(ROOT .. 'terrain'),
  require(ROOT .. 'stress'),
  (require(ROOT .. 'platformer')), -- (parenthesised: Lua 5.4's require returns a second value)
  (require(ROOT .. 'tiled')),
}
