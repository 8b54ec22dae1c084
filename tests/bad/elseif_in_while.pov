// #elseif in a #while is not its own.
#while (0)
#elseif (1)
#end
