-- LÖVE 11.4 configuration for strike's interactive demo (run `love demo` from the
-- repository root). No audio: the demo makes no sound, and without the audio modules
-- LÖVE does not open a sound device (which fails noisily on machines without one).
function love.conf(t)
  t.identity = 'strike-demo'
  t.version = '11.4'
  t.window.title = 'strike demo'
  t.window.width = 800
  t.window.height = 600
  t.window.resizable = false
  t.window.vsync = 1
  t.modules.audio = false
  t.modules.sound = false
  t.modules.joystick = false
  t.modules.physics = false
  t.modules.video = false
end
