// pat_waveforms.pov (bench/pov_cover.sh): waveforms
#version 3.7;
#declare P = pigment { gradient y frequency 2 triangle_wave color_map { [0 rgb <0.1, 0.3, 0>] [1 rgb <0.9, 1, 0.6>] } }
#include "pat_stage.inc"
