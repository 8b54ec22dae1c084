// #elseif without #if.
sphere { 0, 1 }
#elseif (1)
