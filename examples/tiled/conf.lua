-- LÖVE 11.4 configuration of the Tiled level example (`love examples/tiled` from the
-- repository's root). No sound modules: the example makes no sound, and LÖVE then opens no
-- sound device.
function love.conf(t)
  t.identity = 'strike-tiled'
  t.version = '11.4'
  t.window.title = 'strike: a level from Tiled'
  t.window.width = 800
  t.window.height = 600
  t.modules.audio = false
  t.modules.sound = false
  t.modules.joystick = false
  t.modules.physics = false
  t.modules.video = false
end
