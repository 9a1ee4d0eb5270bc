; first thing said
   ;   second, indented   
;
