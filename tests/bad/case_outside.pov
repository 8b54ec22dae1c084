// #case outside a #switch.
#case (1)
