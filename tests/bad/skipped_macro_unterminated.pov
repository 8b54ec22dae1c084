// The #end of a skipped #macro is the macro's, so the #if stays open.
#if (0)
  #macro M()
    sphere { 0, 1 }
  #end
