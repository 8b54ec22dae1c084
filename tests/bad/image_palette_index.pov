// a palette index is 0 to 255
sphere { 0, 1 pigment { image_map { png "t.png" transmit 300, 1 } } }
