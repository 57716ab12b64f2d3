-- LÖVE 11.4 configuration of the top-down shooter example (`love examples/shooter` from the
-- repository's root). No sound modules: the example makes no sound, and LÖVE then opens no
-- sound device.
function love.conf(t)
  t.identity = 'strike-shooter'
  t.version = '11.4'
  t.window.title = 'strike: top-down shooter'
  t.window.width = 800
  t.window.height = 600
  t.modules.audio = false
  t.modules.sound = false
  t.modules.joystick = false
  t.modules.physics = false
  t.modules.video = false
end
