// macro_block_local: a #local whose value is a block a macro call gives (transforms.inc's Spline_Trans:
// #local Matrix = Matrix_Trans(...)) is the caller's local, though the block ends where the called
// macro's body ends; the callee's locals and parameters do not leak. macro_block_local.stderr is what
// povray 3.7.0 printed; the sphere's transform is rotate 10*z translate 80*x.
#macro MT(A) #local Q = A*10; transform { translate Q*x } #end
#macro Foo(B)
 #local M = MT(2)
 #ifdef (A) #debug "A leaked\n" #end
 #ifdef (Q) #debug "Q leaked\n" #end
 #local M2 = MT(B)
 #local M = MT(3)
 transform { rotate 10*z transform M transform M2 }
#end
#declare C = 5;
sphere { 0, 1 transform { Foo(C) } }
#ifdef (M) #debug "M leaked\n" #end
#debug "done\n"
