// POV-Ray's internal font 2 is cyrvetic.ttf, looked for as a ttf file (here neither beside the
// scene nor in a -I folder: benchmark.pov finds it in povray-includes' folder)
text { internal 2 "circe" 0.5, 0 }
