// #default takes a texture: a material of another kind is refused.
#declare Skin = material { skin { } }
#default { texture { Skin } }
