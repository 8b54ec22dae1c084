#declare C = color red <1, 0, 0>;
