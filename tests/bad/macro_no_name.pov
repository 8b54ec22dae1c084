#macro (A) #end
