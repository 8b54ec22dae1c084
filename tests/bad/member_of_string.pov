#declare S = "abc";
#declare X = S.x;
