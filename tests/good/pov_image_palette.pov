// A palette image_map's per-index filter and transmit (POV-Ray's `transmit I, F`), and filter all.
polygon { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <-1, -1, 0>
  pigment { image_map { png "tiny.png" once transmit 5, 1 transmit 0 0.8 filter 2, 0.3 } } }
sphere { 0, 1 pigment { image_map { png "tiny.png" transmit 1, 0.5 transmit all 0.2 } } }
