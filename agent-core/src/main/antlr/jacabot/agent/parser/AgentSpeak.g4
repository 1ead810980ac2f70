grammar AgentSpeak;

// Placeholder for the foundation: literals only. Replaced by the full Jason grammar (issue 3).
literalFile : literal EOF ;
literal     : TILDE? ATOM ( '(' term ( ',' term )* ')' )? ;
term        : literal | VAR | NUMBER | STRING ;

TILDE  : '~' ;
ATOM   : [a-z] [a-zA-Z0-9_]* ;
VAR    : [A-Z_] [a-zA-Z0-9_]* ;
NUMBER : [0-9]+ ( '.' [0-9]+ )? ;
STRING : '"' ( ~["\\\r\n] | '\\' . )* '"' ;
WS     : [ \t\r\n]+ -> skip ;
