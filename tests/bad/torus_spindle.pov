// a spindle torus (minor radius over the major)
torus { 0.5, 1 }
