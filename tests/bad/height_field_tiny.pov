height_field { png "tiny_hf.png" }
