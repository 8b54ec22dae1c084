// POV-Ray's light_group (Parse_Light_Group): its lights light its objects only (group 1 here), a
// group inside it (2) has its own lights and its parent's; global_lights (off by default, a bare
// word is on) lets the scene's other lights in, the outermost group's word counting. The group's
// transforms move its lights and objects. A group without lights warns (3).
light_source { <0, 10, 0> color 1 }
light_group {
  light_source { <1, 2, 3> color 0.5 }
  sphere { 0, 1 }
  light_group { light_source { <0, 5, 0> color 1 } box { -1, 1 } global_lights on }
  translate x
}
light_group { sphere { 2, 1 } global_lights }
