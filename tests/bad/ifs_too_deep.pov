// Nested #if deeper than the depth limit.
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
#end
