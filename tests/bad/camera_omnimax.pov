camera { omnimax location <0, 0, -5> }
