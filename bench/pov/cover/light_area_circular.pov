// light_area_circular.pov (bench/pov_cover.sh): a circular oriented area_light seen side-on: its disk faces each point lit
#include "light_stage.inc"
light_source { <5, 5, -3> color rgb 1 area_light <3, 0, 0>, <0, 3, 0>, 7, 7 jitter circular orient }
