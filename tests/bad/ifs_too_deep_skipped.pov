// Block directives open at once past the depth limit, all but the outer one in a skipped branch.
#if (0)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
#if (1)
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
