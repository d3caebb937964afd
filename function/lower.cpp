// Stack code to register code (register_code.hpp). The stack is simulated: a pushed argument,
// constant or local stays a reference to its register (no instruction), and an operation
// writes its result into the register of the stack slot it leaves it in. Where values must
// lie in their slots, they are moved there first: the arguments of a call (contiguous), every
// value still on the stack at a jump or a jump's target (both paths must agree), and a
// local's stale references before the local is set.
#include <algorithm>
#include <stdexcept>
#include <utility>

#include "function/register_code.hpp"
#include "function/vm.hpp"

namespace lumen::fn {

namespace {

// The operations that pop two operands and push one result, and their register forms.
constexpr std::pair<Op, ROp> kBinary[] = {
    {Op::Add, ROp::Add}, {Op::Sub, ROp::Sub}, {Op::Mul, ROp::Mul}, {Op::Div, ROp::Div},
    {Op::Lt, ROp::Lt},   {Op::Le, ROp::Le},   {Op::Eq, ROp::Eq},   {Op::Ne, ROp::Ne},
    {Op::Ge, ROp::Ge},   {Op::Gt, ROp::Gt},   {Op::And, ROp::And}, {Op::Or, ROp::Or},
    {Op::Min, ROp::Min}, {Op::Max, ROp::Max}, {Op::Math2, ROp::Math2}};

class Lowering {
public:
    explicit Lowering(const Program& p) : p_(p) {
        out_.frame_consts = std::min<int>(int(p.consts.size()), kFrameConsts);
        int locals = 0;
        for (const Instr& in : p.code) {
            if (in.op == Op::Arg) out_.args = std::max<int>(out_.args, int(in.a) + 1);
            if (in.op == Op::Local || in.op == Op::SetLocal) locals = std::max<int>(locals, int(in.a) + 1);
            if (is_jump(in.op)) targets_.push_back(in.a);
        }
        out_.args = std::max(out_.args, p.params);
        locals_ = out_.frame_consts + out_.args;
        slots_ = locals_ + locals;
        std::sort(targets_.begin(), targets_.end());
        label_depth_.assign(p.code.size() + 1, -1);
        new_pc_.assign(p.code.size() + 1, 0);
    }

    RegisterCode run() {
        bool live = true;  // false after an unconditional jump, until the next target
        for (size_t pc = 0; pc <= p_.code.size(); ++pc) {
            if (std::binary_search(targets_.begin(), targets_.end(), uint32_t(pc))) {
                if (live) {
                    materialize_all();
                    label_depth_[pc] = int(stack_.size());
                } else {
                    stack_.clear();
                    for (int k = 0; k < std::max(label_depth_[pc], 0); ++k) stack_.push_back(slot(k));
                }
                live = true;
                new_pc_[pc] = uint32_t(out_.code.size());
            }
            if (pc == p_.code.size()) break;
            if (!live) continue;  // unreachable code
            live = step(p_.code[pc]);
        }
        if (stack_.empty()) emit({ROp::Return, 0, 0, 0, 0, 1});
        else emit({ROp::Return, 0, 0, stack_.back()});
        for (const size_t at : jumps_) out_.code[at].a = new_pc_[out_.code[at].a];
        out_.frame = slots_ + max_depth_ + 1;  // + 1: a scratch register above the stack
        return std::move(out_);
    }

private:
    static bool is_jump(Op op) {
        return op == Op::Jump || op == Op::JumpIfNotNeg || op == Op::JumpIfNotZero ||
               op == Op::JumpIfGreater;
    }
    uint16_t slot(size_t k) const { return uint16_t(slots_ + int(k)); }
    void emit(const RInstr& in) { out_.code.push_back(in); }

    void push(uint16_t reg) {
        stack_.push_back(reg);
        max_depth_ = std::max(max_depth_, int(stack_.size()));
        // The compiler's limits (kMaxStack, kMaxLocals, kMaxParams) keep within it.
        if (slots_ + max_depth_ + 1 > kMaxFrame) throw std::length_error("function frame too large");
    }
    uint16_t pop() {
        const uint16_t r = stack_.back();
        stack_.pop_back();
        return r;
    }
    void materialize(size_t k) {
        if (stack_[k] == slot(k)) return;
        emit({ROp::Move, 0, slot(k), stack_[k]});
        stack_[k] = slot(k);
    }
    void materialize_all() {
        for (size_t k = 0; k < stack_.size(); ++k) materialize(k);
    }
    // Constant i's register: its own, or the scratch slot above the stack loaded with it.
    uint16_t constant(uint32_t i) {
        if (int(i) < out_.frame_consts) return uint16_t(i);
        const uint16_t scratch = slot(stack_.size());
        emit({ROp::LoadConst, 0, scratch, 0, 0, i});
        return scratch;
    }
    // Pops `count` operands into their slots (contiguous), returning the first slot.
    uint16_t pop_contiguous(int count) {
        const size_t first = stack_.size() - size_t(count);
        for (size_t k = first; k < stack_.size(); ++k) materialize(k);
        stack_.resize(first);
        return slot(first);
    }
    // An operation's result, left in the slot of the stack's top.
    void result(const RInstr& in) {
        emit(in);
        push(in.d);
    }
    void unary(ROp op, uint32_t a = 0) {
        const uint16_t s = pop();
        result({op, 0, slot(stack_.size()), s, 0, a});
    }
    void binary(ROp op, uint32_t a = 0) {
        const uint16_t t = pop(), s = pop();
        result({op, 0, slot(stack_.size()), s, t, a});
    }
    void jump(ROp op, uint16_t s, uint16_t t, uint32_t target) {
        materialize_all();
        if (target < label_depth_.size()) label_depth_[target] = int(stack_.size());
        jumps_.push_back(out_.code.size());
        emit({op, 0, 0, s, t, target});
    }

    // Lowers one instruction; false when what follows is unreachable.
    bool step(const Instr& in) {
        for (const auto& [op, rop] : kBinary)
            if (in.op == op) {
                binary(rop, in.a);
                return true;
            }
        switch (in.op) {
            case Op::Const:
                push(constant(in.a));  // a loaded one lies in the slot it is pushed to
                break;
            case Op::Arg: push(uint16_t(out_.frame_consts + int(in.a))); break;
            case Op::Local: push(uint16_t(locals_ + int(in.a))); break;
            case Op::SetLocal: {
                const uint16_t local = uint16_t(locals_ + int(in.a));
                const uint16_t value = pop();
                for (size_t k = 0; k < stack_.size(); ++k)
                    if (stack_[k] == local) materialize(k);
                emit({ROp::Move, 0, local, value});
                break;
            }
            case Op::Neg: unary(ROp::Neg); break;
            case Op::AddConst: case Op::SubConst: case Op::MulConst: {
                const uint16_t t = constant(in.a);  // (a loaded one lies above the top)
                const uint16_t s = pop();
                const ROp op = in.op == Op::AddConst ? ROp::Add
                               : in.op == Op::SubConst ? ROp::Sub : ROp::Mul;
                result({op, 0, slot(stack_.size()), s, t});
                break;
            }
            case Op::Math1: unary(ROp::Math1, in.a); break;
            case Op::Jump: jump(ROp::Jump, 0, 0, in.a); return false;
            case Op::JumpIfNotNeg: {
                const uint16_t s = pop();
                jump(ROp::JumpIfNotNeg, s, 0, in.a);
                break;
            }
            case Op::JumpIfNotZero: {
                const uint16_t s = pop();
                jump(ROp::JumpIfNotZero, s, 0, in.a);
                break;
            }
            case Op::JumpIfGreater: {
                const uint16_t t = pop(), s = pop();
                jump(ROp::JumpIfGreater, s, t, in.a);
                break;
            }
            case Op::Internal: call(ROp::Internal, in, in.b); break;
            case Op::Call: call(ROp::Call, in, in.b); break;
            case Op::External: call(ROp::External, in, 3); break;
            case Op::Transform: call(ROp::Transform, in, 3); break;
            default: break;  // the binary operations (kBinary), lowered above
            case Op::Spline: {
                const uint16_t s = pop();
                result({ROp::Spline, in.c, slot(stack_.size()), s, 0, in.a});
                break;
            }
        }
        return true;
    }
    void call(ROp op, const Instr& in, int count) {
        const uint16_t first = pop_contiguous(count);
        result({op, in.c, first, first, 0, in.a});
    }

    const Program& p_;
    RegisterCode out_;
    int locals_ = 0, slots_ = 0, max_depth_ = 0;
    std::vector<uint16_t> stack_;  // each stack entry's register
    std::vector<uint32_t> targets_;
    std::vector<int> label_depth_;   // per old pc: the stack depth jumps bring there
    std::vector<uint32_t> new_pc_;   // per old pc that is a target: its new pc
    std::vector<size_t> jumps_;      // new jump instructions, to retarget
};

}  // namespace

RegisterCode lower(const Program& program) { return Lowering(program).run(); }

}  // namespace lumen::fn
