/* Jason's project files (.mas2j), as far as a local infrastructure needs them. */
grammar Mas2j;

project      : 'MAS' ID '{' setting* '}' EOF ;
setting      : 'infrastructure' ':' ID ( '(' ~')'* ')' )?           # infrastructure
             | 'environment' ':' className arguments? ( 'at' STRING )?  # environment
             | 'executionControl' ':' className arguments?          # executionControl
             | 'agents' ':' agentDecl*                              # agents
             | 'aslSourcePath' ':' STRING ( ';' STRING )* ';'?      # aslSourcePath
             | 'classpath' ':' STRING ( ';' STRING )* ';'?          # classpath
             | 'directives' ':' ~';'* ';'                           # directives
             ;
agentDecl    : agentName fileName? optionList? archClass* ( '#' NUMBER | 'at' STRING )* ';' ;
// as Jason, 'at' cannot name an agent (it introduces the host)
agentName    : ID ;
fileName     : ( ID | STRING ) ( '.' ID )* ;
optionList   : '[' ( option ( ',' option )* )? ']' ;
option       : ID '=' ( ID | NUMBER | STRING ) ;
archClass    : kind=( 'agentArchClass' | 'agentClass' | 'beliefBaseClass' ) className arguments? ;
className    : ID ( '.' ID )* ;
arguments    : '(' ( argument ( ',' argument )* )? ')' ;
// a structure, as in CArtAgO's ("standalone", protocol(lipermi)), reaches the class as its text
argument     : NUMBER | STRING | className arguments? | '-' NUMBER ;

ID      : [a-zA-Z_] [a-zA-Z0-9_\-]* ;
NUMBER  : [0-9]+ ( '.' [0-9]+ )? ;
STRING  : '"' ( ~["\\\r\n] | '\\' . )* '"' ;
LINE_COMMENT  : '//' ~[\r\n]* -> skip ;
BLOCK_COMMENT : '/*' .*? '*/' -> skip ;
WS      : [ \t\r\n\f]+ -> skip ;
ERROR_CHAR : . ;
