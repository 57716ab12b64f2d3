-- LÖVE 11.4 configuration of the platformer example (`love examples/platformer` from the
-- repository's root). No sound modules: the example makes no sound, and LÖVE then opens no
-- sound device.
function love.conf(t)
  t.identity = 'strike-platformer'
  t.version = '11.4'
  t.window.title = 'strike: platformer'
  t.window.width = 800
  t.window.height = 600
  t.modules.audio = false
  t.modules.sound = false
  t.modules.joystick = false
  t.modules.physics = false
  t.modules.video = false
end
