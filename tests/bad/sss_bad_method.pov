sphere { 0, 1 material { skin { method fast } } }
