// Runaway recursion: Down never stops; the error names the call chain.
#macro Down(N)
  Down(N + 1)
#end
Down(0)
