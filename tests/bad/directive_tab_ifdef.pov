// A tab between # and the name.
#	ifdef (A)
#end
