/*
 * AgentSpeak as Jason 3.2 reads it (our own grammar, written from Jason's documented syntax).
 * Operator precedence, from loosest to tightest: | , & , not , relational (< <= > >= == \== = =..),
 * + - , * / div mod , ** (right associative), unary + - .
 */
grammar AgentSpeak;

agent       : component* EOF ;
termOnly    : term EOF ;
planOnly    : plan EOF ;
component   : directive | belief | initialGoal | plan ;

directive   : '{' begin='begin' literal '}' | '{' literal '}' ;
belief      : literal ( ':-' logExpr )? '.' ;
initialGoal : '!' literal '.' ;

// a goal condition (Jason 3.2's '<:'): the goal is achieved as soon as it holds
plan        : planLabel? trigger ( ':' logExpr )? ( '<:' goalCondition=logExpr )? ( '<-' planBody )? '.' ;
planLabel   : '@' ( literal | list ) ;
trigger     : op=( '+' | '-' | '^' ) kind=( '!' | '?' )? literal ;

// A plan body: formulas separated by ';'. if/while/for need no ';' after their closing brace.
planBody    : bodyItem ( ';' bodyItem | {_input.LA(-1) == RBRACE}? bodyItem )* ';'? ;
bodyItem    : statement | forkFormula ;

// B1 ||| B2: concurrent branches, the first to end wins; B1 |&| B2: all must end (|&| binds
// tighter). A branch is a formula or a parenthesised body. Both become Jason's .fork(or|and, ...).
forkFormula : forkAnd ( '|||' forkAnd )* ;
forkAnd     : forkOperand ( '|&|' forkOperand )* ;
forkOperand : bodyFormula | '(' planBody ')' ;

statement   : 'if' '(' logExpr ')' block elifPart* elsePart?    # ifStatement
            | 'while' '(' logExpr ')' block                      # whileStatement
            | 'for' '(' logExpr ')' block                        # forStatement
            ;
elifPart    : 'elif' '(' logExpr ')' block ;
elsePart    : 'else' block ;
block       : '{' planBody? RBRACE ;

bodyFormula : '!' literal                       # achieve
            | '!!' literal                      # achieveNewFocus
            | '?' logExpr                       # testGoal
            | '+' '+' logExpr                   # addBelNewFocus
            | '+' '<' logExpr                   # addBelBegin
            | '+' '>' logExpr                   # addBelEnd
            | '-' '+' logExpr                   # delAddBel
            | '-' '-' logExpr                   # delBelNewFocus
            | '+' logExpr                       # addBel
            | '-' logExpr                       # delBel
            | logExpr                           # actionOrConstraint
            ;

logExpr     : logTerm ( '|' logExpr )? ;
logTerm     : logFactor ( '&' logTerm )? ;
logFactor   : 'not' logFactor                   # notFactor
            | relExpr                           # relFactor
            ;
relExpr     : relOperand ( op=( '<' | '<=' | '>' | '>=' | '==' | '\\==' | '=' | '=..' ) relOperand )? ;
relOperand  : arithExpr | STRING | list | braceTerm ;

arithExpr   : arithTerm ( op+=( '+' | '-' ) arithTerm )* ;
arithTerm   : arithFactor ( op+=( '*' | '/' | 'div' | 'mod' ) arithFactor )* ;
arithFactor : arithSimple ( '**' arithFactor )? ;
arithSimple : sign=( '+' | '-' )? ( NUMBER | '(' logExpr ')' | literal ) ;

literal     : 'true'                                                       # trueLiteral
            | 'false'                                                      # falseLiteral
            | nsPrefix? neg='~'? name=( ATOM | 'begin' | 'end' ) ( '(' terms ')' )? annots?  # structure
            | nsPrefix? neg='~'? VAR annots?                               # varLiteral
            | nsPrefix? neg='~'? UNNAMEDVAR annots?                        # unnamedVarLiteral
            ;
// a namespace: ns::b, NS::b, _::b, and ::b (the namespace the file is read in); the prefix is one
// token, so that ns::X is never read as the atom ns followed by ::X
nsPrefix    : ns=( NS_ATOM | NS_VAR ) | '::' ;
terms       : term ( ',' term )* ;
term        : logExpr ;

list        : '[' ( listElement ( ',' listElement )* ( '|' listTail )? )? ']' ;
listElement : arithExpr | STRING | list | braceTerm ;
listTail    : VAR | UNNAMEDVAR | list ;
// a literal's annotations, which (as Jason's) may be a tail alone: b[|T]
annots      : list | '[' '|' listTail ']' ;

// { +b }, { +!g : c <- body }, { a; b }, { h :- body }
braceTerm   : '{' ( planLabel? trigger ( ':' logExpr )? ( '<-' planBody )?
                  | planBody ( ':-' logExpr )? )? RBRACE ;

RBRACE      : '}' ;
NUMBER      : DIGIT+
            | DIGIT* '.' DIGIT+ EXPONENT?
            | DIGIT+ EXPONENT ;
STRING      : '"' ( ~["\\\r\n] | '\\' . )* '"' ;
NS_ATOM     : LC_LETTER CHAR* '::' ;
NS_VAR      : ( UC_LETTER | '_' ) CHAR* '::' ;
ATOM        : ( LC_LETTER | '.' CHAR ) ( CHAR | '.' CHAR )*
            | '\'' ~[']* '\'' ;
VAR         : UC_LETTER CHAR* ;
UNNAMEDVAR  : '_' CHAR* ;

LINE_COMMENT  : '//' ~[\r\n]* -> skip ;
BLOCK_COMMENT : '/*' .*? '*/' -> skip ;
WS            : [ \t\r\n\f]+ -> skip ;
// Anything else is a lexical error reported with its position.
ERROR_CHAR    : . ;

fragment EXPONENT  : [eE] [+-]? DIGIT+ ;
fragment CHAR      : LC_LETTER | UC_LETTER | DIGIT | '_' ;
fragment LC_LETTER : [a-z] ;
fragment UC_LETTER : [A-Z] ;
fragment DIGIT     : [0-9] ;
