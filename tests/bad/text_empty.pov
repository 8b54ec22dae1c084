// an empty string makes no text
text { ttf "timrom.ttf" "" 0.5, 0 }
