package jacabot.agent.parser;

import jacabot.agent.parser.AgentSpeakParser.*;
import jacabot.agent.syntax.AnnotatedVar;
import jacabot.agent.syntax.ArithExpr;
import jacabot.agent.syntax.ArithFunction;
import jacabot.agent.syntax.BodyStep;
import jacabot.agent.syntax.BodyStep.Kind;
import jacabot.agent.syntax.BodyTerm;
import jacabot.agent.syntax.Literal;
import jacabot.agent.syntax.LogExpr;
import jacabot.agent.syntax.PlanTerm;
import jacabot.agent.syntax.RelExpr;
import jacabot.agent.syntax.SourceInfo;
import jacabot.agent.syntax.Term;
import jacabot.agent.syntax.Var;
import java.util.ArrayList;
import java.util.List;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * Builds plan bodies for {@link AstBuilder}: body formulas, {@code if}/{@code while}/{@code for}
 * as Jason's {@code .if_then_else}, {@code .loop} and {@code .foreach}, and the fork operators as
 * {@code .fork}; the formulas in them are the builder's. As in Jason, the bodies these make are
 * printed bare ({@code .if_then_else(c,a; b)}), and a braced body written as a formula
 * ({@code { a; b }; c}) is flattened into the body round it.
 */
final class BodyBuilder {
    private final AstBuilder ast;

    BodyBuilder(AstBuilder ast) {
        this.ast = ast;
    }

    BodyTerm planBody(PlanBodyContext ctx) {
        var steps = new ArrayList<BodyStep>();
        for (BodyItemContext item : ctx.bodyItem()) {
            if (item.statement() != null) {
                steps.add(statement(item.statement()));
            } else {
                steps.addAll(fork(item.forkFormula()));
            }
        }
        return new BodyTerm(steps);
    }

    /** {@return a body a statement or a fork made: Jason prints it without braces} */
    private static BodyTerm bare(List<BodyStep> steps) {
        return new BodyTerm(steps, false);
    }

    /** {@code B1 ||| B2} and {@code B1 |&| B2} as {@code .fork(or|and, {B1}, {B2})}; a lone operand stays as it is. */
    private List<BodyStep> fork(ForkFormulaContext ctx) {
        return forkStep("or", ctx.forkAnd().stream().map(this::forkAnd).toList(), ctx);
    }

    private List<BodyStep> forkAnd(ForkAndContext ctx) {
        return forkStep("and", ctx.forkOperand().stream().map(this::forkOperand).toList(), ctx);
    }

    private List<BodyStep> forkStep(String kind, List<List<BodyStep>> operands, ParserRuleContext ctx) {
        if (operands.size() == 1) {
            return operands.get(0);
        }
        var branches = new ArrayList<Term>();
        branches.add(Literal.atom(kind));
        operands.forEach(o -> branches.add(bare(o)));
        return List.of(new BodyStep(Kind.INTERNAL_ACTION, Literal.of(".fork", branches.toArray(new Term[0])), ast.where(ctx)));
    }

    private List<BodyStep> forkOperand(ForkOperandContext ctx) {
        return ctx.bodyFormula() != null ? bodyFormulas(ctx.bodyFormula()) : planBody(ctx.planBody()).steps();
    }

    private BodyTerm block(BlockContext ctx) {
        return bare(ctx.planBody() == null ? List.of() : planBody(ctx.planBody()).steps());
    }

    private BodyStep statement(StatementContext ctx) {
        SourceInfo src = ast.where(ctx);
        if (ctx instanceof IfStatementContext s) {
            return ifChain(s.logExpr(), s.block(), s.elifPart(), 0, s.elsePart(), src);
        }
        if (ctx instanceof WhileStatementContext s) {
            return new BodyStep(Kind.INTERNAL_ACTION,
                    Literal.of(".loop", ast.logExpr(s.logExpr()), block(s.block())), src);
        }
        ForStatementContext s = (ForStatementContext) ctx;
        return new BodyStep(Kind.INTERNAL_ACTION,
                Literal.of(".foreach", ast.logExpr(s.logExpr()), block(s.block())), src);
    }

    /** if/elif/else becomes nested {@code .if_then_else(Cond, {Then}, {Else})}, as in Jason. */
    private BodyStep ifChain(LogExprContext cond, BlockContext then, List<ElifPartContext> elifs, int next,
            ElsePartContext elsePart, SourceInfo src) {
        BodyTerm elseBody = null;
        if (next < elifs.size()) {
            ElifPartContext e = elifs.get(next);
            elseBody = bare(List.of(ifChain(e.logExpr(), e.block(), elifs, next + 1, elsePart, ast.where(e))));
        } else if (elsePart != null) {
            elseBody = block(elsePart.block());
        }
        Term c = ast.logExpr(cond);
        Literal ite = elseBody == null
                ? Literal.of(".if_then_else", c, block(then))
                : Literal.of(".if_then_else", c, block(then), elseBody);
        return new BodyStep(Kind.INTERNAL_ACTION, ite, src);
    }

    /** {@return the steps of a formula: one, or those of a braced body written as a formula} */
    private List<BodyStep> bodyFormulas(BodyFormulaContext ctx) {
        if (ctx instanceof ActionOrConstraintContext c) {
            Term t = ast.logExpr(c.logExpr());
            return t instanceof BodyTerm b ? b.steps() : List.of(actionOrConstraint(t, ast.where(ctx)));
        }
        return List.of(bodyFormula(ctx));
    }

    private BodyStep actionOrConstraint(Term t, SourceInfo src) {
        if (t instanceof Literal l) {
            return new BodyStep(l.isInternalAction() ? Kind.INTERNAL_ACTION : Kind.ACTION, l, src);
        }
        if (t instanceof Var || t instanceof AnnotatedVar || t instanceof ArithFunction) {
            // a function call written as a formula is, as in Jason, an action for the environment
            return new BodyStep(Kind.ACTION, t, src);
        }
        if (t instanceof RelExpr) {
            return new BodyStep(Kind.CONSTRAINT, t, src);
        }
        if (t instanceof LogExpr) {
            // Jason's parser makes a logical formula (`not b`, `a & b`) a step for the environment,
            // not a constraint: its LogExpr is a Literal there, and only a relation is a constraint
            return new BodyStep(Kind.ACTION, t, src);
        }
        if (!missingSemicolon(t)) {
            ast.error(src, "'" + t + "' is not a valid plan body formula");
        }
        return new BodyStep(Kind.CONSTRAINT, Literal.TRUE, src);
    }

    /** Every formula but an action or a constraint, which {@link #bodyFormulas} makes. */
    private BodyStep bodyFormula(BodyFormulaContext ctx) {
        SourceInfo src = ast.where(ctx);
        if (ctx instanceof AchieveContext c) {
            return new BodyStep(Kind.ACHIEVE, ast.literal(c.literal()), src);
        }
        if (ctx instanceof AchieveNewFocusContext c) {
            return new BodyStep(Kind.ACHIEVE_NEW_FOCUS, ast.literal(c.literal()), src);
        }
        if (ctx instanceof TestGoalContext c) {
            return new BodyStep(Kind.TEST, ast.logExpr(c.logExpr()), src);
        }
        Kind kind;
        LogExprContext operand;
        if (ctx instanceof AddBelContext c) {
            kind = Kind.ADD_BEL;
            operand = c.logExpr();
        } else if (ctx instanceof AddBelBeginContext c) {
            kind = Kind.ADD_BEL;
            operand = c.logExpr();
        } else if (ctx instanceof AddBelEndContext c) {
            kind = Kind.ADD_BEL_END;
            operand = c.logExpr();
        } else if (ctx instanceof AddBelNewFocusContext c) {
            kind = Kind.ADD_BEL_NEW_FOCUS;
            operand = c.logExpr();
        } else if (ctx instanceof DelBelContext c) {
            kind = Kind.DEL_BEL;
            operand = c.logExpr();
        } else if (ctx instanceof DelBelNewFocusContext c) {
            kind = Kind.DEL_BEL_NEW_FOCUS;
            operand = c.logExpr();
        } else {
            kind = Kind.DEL_ADD_BEL;
            operand = ((DelAddBelContext) ctx).logExpr();
        }
        Term t = ast.logExpr(operand);
        if (t instanceof PlanTerm) {
            // as Jason: +{plan} is .add_plan(plan, self, begin), +>{plan} adds at the end, -{plan} removes
            if (kind == Kind.ADD_BEL || kind == Kind.ADD_BEL_END) {
                Term at = Literal.atom(kind == Kind.ADD_BEL ? "begin" : "end");
                return new BodyStep(Kind.INTERNAL_ACTION, Literal.of(".add_plan", t, Literal.SELF, at), src);
            }
            if (kind == Kind.DEL_BEL) {
                return new BodyStep(Kind.INTERNAL_ACTION, Literal.of(".remove_plan", t), src);
            }
            ast.error(src, "wrong combination of operator '" + kind.prefix() + "' and a plan");
            return new BodyStep(kind, Literal.TRUE, src);
        }
        if (!(t instanceof Literal) && !(t instanceof Var) && !(t instanceof AnnotatedVar)) {
            if (!missingSemicolon(t)) {
                ast.error(src, "the operand of '" + kind.prefix() + "' must be a literal, not '" + t + "'");
            }
            t = Literal.TRUE;
        } else if (t instanceof Literal l && l.isInternalAction()) {
            ast.error(src, "wrong combination of operator '" + kind.prefix() + "' and internal action " + l);
        }
        return new BodyStep(kind, t, src);
    }

    /**
     * Whether a formula is {@code a(1) -b} read as arithmetic, as Jason reads {@code +a(1) -b}: the
     * error at its operand that is no number is told already, and gets the likely cause (a {@code ;} left out
     * between two formulas); nothing more is told of it.
     */
    private boolean missingSemicolon(Term t) {
        if (!(t instanceof ArithExpr a) || (a.op() != ArithExpr.Op.PLUS && a.op() != ArithExpr.Op.MINUS)) {
            return false;
        }
        if (a.left() instanceof ArithExpr) {
            return missingSemicolon(a.left());
        }
        String which = AstBuilder.notNumeric(a.left()) ? "first" : AstBuilder.notNumeric(a.right()) ? "second" : null;
        if (which == null) {
            return false;
        }
        ast.amend(a.src(), AstBuilder.operandError("ArithExpr", which, which.equals("first") ? a.left() : a.right()),
                " (a ';' missing before '" + a.op() + a.right() + "'?)");
        return true;
    }
}
