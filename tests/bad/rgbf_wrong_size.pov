#declare C = rgbf <1, 0, 0>;
