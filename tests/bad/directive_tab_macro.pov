// A tab between # and the name.
#	macro M()
#end
