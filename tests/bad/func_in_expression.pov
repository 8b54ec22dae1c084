#declare P = 2 + function { x };
