// pat_cells.pov (bench/pov_cover.sh): cells
#version 3.7;
#declare P = pigment { cells scale 0.5 color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1 rgb <0, 0, 1>] } }
#include "pat_stage.inc"
