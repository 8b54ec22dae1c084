// a font found neither beside the scene nor in a -I folder
text { ttf "no_such_font.ttf" "circe" 0.5, 0 }
