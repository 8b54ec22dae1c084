#declare X = 1 + Nowhere(2);
