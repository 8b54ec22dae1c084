// transform Name needs a declared transform.
#declare X = 1;
sphere { 0, 1 transform X }
