// Pigments nest at most 16 deep in maps and lists.
#declare P = pigment { checker rgb 0, pigment { checker rgb 0, pigment { checker rgb 0, pigment { checker rgb 0,
  pigment { checker rgb 0, pigment { checker rgb 0, pigment { checker rgb 0, pigment { checker rgb 0,
  pigment { checker rgb 0, pigment { checker rgb 0, pigment { checker rgb 0, pigment { checker rgb 0,
  pigment { checker rgb 0, pigment { checker rgb 0, pigment { checker rgb 0, pigment { checker rgb 0,
  pigment { checker rgb 0, rgb 1 } } } } } } } } } } } } } } } } }
