--- LÖVE configuration of bench/lovephysics (see main.lua): no window, no graphics, no
--- audio; only what love.physics and the timer need.
function love.conf(t)
  t.window = false
  t.console = false
  t.modules.audio = false
  t.modules.data = true
  t.modules.event = true
  t.modules.font = false
  t.modules.graphics = false
  t.modules.image = false
  t.modules.joystick = false
  t.modules.keyboard = false
  t.modules.math = false
  t.modules.mouse = false
  t.modules.physics = true
  t.modules.sound = false
  t.modules.system = false
  t.modules.thread = false
  t.modules.timer = true
  t.modules.touch = false
  t.modules.video = false
  t.modules.window = false
end
