// materials.pov: skin, wax and marble blocks (their coat over the interior) beside a textured box,
// under one light and a background; instances of one declared sphere share its geometry.
// render: -W 64 -H 48 --spp 16 --seed 4
// compare: --fail 0.05 --fail-percent 1
camera { location <0, 1.5, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <-4, 6, -5> color rgb 1 intensity 60 }
sky_sphere { pigment { color rgb <0.25, 0.27, 0.3> } intensity 1 }
#declare Ball = sphere { <0, 0.6, 0>, 0.6 }
object { Ball translate <-1.4, 0, 0> material { skin {} } }
object { Ball material { wax {} } }
object { Ball translate <1.4, 0, 0> material { marble {} } }
box { <-2.5, 0, 1.5>, <2.5, 2, 1.7>
      material { diffuse { image "../../scenes/assets/lee_perry_smith_head/Map-COL.jpg" } } }
plane { y, 0 material { diffuse { color rgb 0.5 } } }
