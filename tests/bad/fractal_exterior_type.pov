// POV-Ray's exterior types are 0 to 8.
sphere { 0, 1 pigment { julia <0, 1>, 10 exterior 9, 1 } }
