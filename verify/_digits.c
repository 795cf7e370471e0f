/* The digits of a row of balls, compiled: verify.result._row_of_balls's loop.
 *
 * row(balls, scales, tens, general, dps) writes a row of a table from its arb balls, as the
 * Python loop of verify.result._row_of_balls does, step by step: the same integer operations
 * (CPython's own integers) up to the truncated digits n, whose division by the cut (a power of
 * ten) and rounding are read off n's decimal text:
 *   - balls: the row's balls;
 *   - scales: verify.result._ROW_SCALES[dps], the scales of the digits by exponent plus bit
 *     count (tuples of verify.result._digit_scale);
 *   - tens: verify.result._TEN_TUPLE, 10.0**j correctly rounded at j + 300;
 *   - general: verify.result._ball_raw, the Python steps of a ball whose radius does not support
 *     every digit (called as general(x, man, exp, dps));
 *   - dps: the digits asked for.
 * It returns (texts, bound): the texts, and the bound's text where doubles decide it (else None:
 * the bound in integers, verify.result._exact_bound).  It returns None where the Python loop
 * must write the row: a scale not kept yet (the Python loop keeps it), a ball the general
 * steps leave to mpmath, or a cut that is not the power of ten n's digits call for (none is
 * met: the tests compare the two loops).  Nothing is kept between calls but the methods of the
 * balls' type.
 *
 * Each step names the line of _row_of_balls it stands for.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>

static PyObject *s_mid, *s_man_exp, *s_rel_accuracy_bits, *s_rad;
/* the cut of a scale is 10**k with k from 5 to 7 (verify.result._digit_scale); up to 18 here,
 * as a Python int and as an integer of 64 bits; at most 1400 digits (_digit_scale's reach) */
#define MAX_CUT 18
#define MAX_DIGITS 1400
/* a ball's binary exponent beyond this goes to the Python loop (exp + bc stays in a long long) */
#define EXP_LIMIT (1LL << 60)
static PyObject *tens_to[MAX_CUT + 1];
static unsigned long long pow10_u64[MAX_CUT + 1];

/* the methods of the balls' type, looked up once per type (a row's balls share one) */
static PyTypeObject *ball_type;
static PyObject *m_mid, *m_man_exp, *m_rel_accuracy_bits, *m_rad;

enum { FAILED = -1, WRITTEN = 0, TO_PYTHON = 1 };

static int
ball_methods(PyObject *x)
{
    PyTypeObject *type = Py_TYPE(x);
    if (type == ball_type)
        return 0;
    PyObject *a = PyObject_GetAttr((PyObject *)type, s_mid);
    PyObject *b = PyObject_GetAttr((PyObject *)type, s_man_exp);
    PyObject *c = PyObject_GetAttr((PyObject *)type, s_rel_accuracy_bits);
    PyObject *d = PyObject_GetAttr((PyObject *)type, s_rad);
    if (!a || !b || !c || !d) {
        Py_XDECREF(a);
        Py_XDECREF(b);
        Py_XDECREF(c);
        Py_XDECREF(d);
        return -1;
    }
    Py_XSETREF(m_mid, a);
    Py_XSETREF(m_man_exp, b);
    Py_XSETREF(m_rel_accuracy_bits, c);
    Py_XSETREF(m_rad, d);
    Py_INCREF(type);
    Py_XSETREF(ball_type, type);
    return 0;
}

/* obj.name(), through the method kept where obj is of the balls' type */
static PyObject *
call0(PyObject *method, PyObject *obj, PyObject *name)
{
    if (Py_TYPE(obj) == ball_type)
        return PyObject_Vectorcall(method, &obj, 1, NULL);
    return PyObject_CallMethodNoArgs(obj, name);
}

/* a Python int as a long long: 0, or -1 with an error set */
static int
as_ll(PyObject *o, long long *out)
{
    long long v = PyLong_AsLongLong(o);
    if (v == -1 && PyErr_Occurred())
        return -1;
    *out = v;
    return 0;
}

/* f"{D[:split]}.{D[split:]}{piece}" (split > 0) or piece + D (split == 0), after a "-" for a
 * negative number; D the nd digits of str(D) */
static PyObject *
write_text(const char *d, Py_ssize_t nd, long long split, PyObject *piece, int negative)
{
    Py_ssize_t np;
    const char *p = PyUnicode_AsUTF8AndSize(piece, &np);
    if (p == NULL)
        return NULL;
    Py_ssize_t length = nd + np + (split ? 1 : 0) + (negative ? 1 : 0);
    PyObject *text = PyUnicode_New(length, 127);
    if (text == NULL)
        return NULL;
    char *out = (char *)PyUnicode_1BYTE_DATA(text);
    if (negative)
        *out++ = '-';
    if (split) {
        Py_ssize_t head = split < nd ? (Py_ssize_t)split : nd;
        memcpy(out, d, head);
        out += head;
        *out++ = '.';
        memcpy(out, d + head, nd - head);
        memcpy(out + nd - head, p, np);
    }
    else {
        memcpy(out, p, np);
        memcpy(out + np, d, nd);
    }
    return text;
}

/* general(x, man, exp, dps), the Python steps of one ball: its text, and its error's double or
 * none (the bound in integers); TO_PYTHON where they leave the row to mpmath */
static int
general_ball(PyObject *general, PyObject *x, PyObject *man, long long exp, PyObject *dps,
             PyObject **text, double *most, int *exact)
{
    PyObject *e = PyLong_FromLongLong(exp);
    if (e == NULL)
        return FAILED;
    PyObject *argv[4] = {x, man, e, dps};
    PyObject *got = PyObject_Vectorcall(general, argv, 4, NULL);
    Py_DECREF(e);
    if (got == NULL)
        return FAILED;
    if (got == Py_None) {
        Py_DECREF(got);
        return TO_PYTHON;
    }
    if (!PyTuple_Check(got) || PyTuple_GET_SIZE(got) != 2) {
        Py_DECREF(got);
        PyErr_SetString(PyExc_TypeError, "general(x, man, exp, dps): (text, error) or None");
        return FAILED;
    }
    PyObject *error = PyTuple_GET_ITEM(got, 1);
    if (error == Py_None) {  /* if dk[0] or bc > 1000: exact = True */
        *exact = 1;
    }
    else {  /* else: e = ldexp(float(mag), exp) + f; if e > most: most = e */
        double v = PyFloat_AsDouble(error);
        if (v == -1.0 && PyErr_Occurred()) {
            Py_DECREF(got);
            return FAILED;
        }
        if (v > *most)
            *most = v;
    }
    *text = PyTuple_GET_ITEM(got, 0);
    Py_INCREF(*text);
    Py_DECREF(got);
    return WRITTEN;
}

/* one ball of the row: its text, with most and wide updated; or TO_PYTHON, or FAILED */
static int
one_ball(PyObject *x, PyObject *scales, PyObject *general, PyObject *dps_obj, long long dps,
         PyObject **text, double *most, double *wide, int *exact)
{
    int status = FAILED;
    PyObject *mid = NULL, *me = NULL, *man = NULL, *mag = NULL, *key = NULL, *count = NULL;
    PyObject *t = NULL, *t2 = NULL, *n = NULL;
    PyObject *digits = NULL;
    long long exp, acc, bc;
    *text = NULL;

    if (ball_methods(x) < 0)
        goto done;
    /* man, exp = x.mid().man_exp(); man = _index(man); exp = _index(exp) */
    mid = call0(m_mid, x, s_mid);
    if (mid == NULL)
        goto done;
    me = call0(m_man_exp, mid, s_man_exp);
    if (me == NULL)
        goto done;
    if (!PyTuple_Check(me) || PyTuple_GET_SIZE(me) != 2) {
        PyErr_SetString(PyExc_TypeError, "man_exp() gave no pair");
        goto done;
    }
    man = PyNumber_Index(PyTuple_GET_ITEM(me, 0));
    if (man == NULL)
        goto done;
    t = PyNumber_Index(PyTuple_GET_ITEM(me, 1));
    if (t == NULL)
        goto done;
    if (as_ll(t, &exp) < 0 || exp > EXP_LIMIT || exp < -EXP_LIMIT) {
        /* an exponent so large that exp + bc could overflow a long long: the Python loop */
        PyErr_Clear();
        status = TO_PYTHON;
        goto done;
    }
    Py_CLEAR(t);
    /* acc = x.rel_accuracy_bits() */
    t = call0(m_rel_accuracy_bits, x, s_rel_accuracy_bits);
    if (t == NULL || as_ll(t, &acc) < 0)
        goto done;
    Py_CLEAR(t);
    /* mag = -man if man < 0 else man; bc = mag.bit_length() */
    int negative = _PyLong_Sign(man) < 0;
    if (negative) {
        mag = PyNumber_Negative(man);
        if (mag == NULL)
            goto done;
    }
    else {
        Py_INCREF(man);
        mag = man;
    }
    size_t bits = _PyLong_NumBits(mag);
    if (bits == (size_t)-1 && PyErr_Occurred())
        goto done;
    bc = (long long)bits;
    /* sc = scales.get(exp + bc); a scale not kept yet: the Python loop makes it */
    key = PyLong_FromLongLong(exp + bc);
    if (key == NULL)
        goto done;
    PyObject *sc = PyDict_GetItemWithError(scales, key); /* borrowed */
    if (sc == NULL) {
        if (!PyErr_Occurred())
            status = TO_PYTHON;
        goto done;
    }
    if (!PyTuple_Check(sc) || PyTuple_GET_SIZE(sc) != 15) {
        PyErr_SetString(PyExc_TypeError, "a scale is a tuple of 15");
        goto done;
    }
    /* if usable <= acc < tiny: every digit usable, r above _TINY */
    long long usable, tiny, unit, shift, fix, split;
    if (as_ll(PyTuple_GET_ITEM(sc, 0), &usable) < 0 || as_ll(PyTuple_GET_ITEM(sc, 1), &tiny) < 0)
        goto done;
    if (!(usable <= acc && acc < tiny)) {  /* else: the general steps (_ball_raw) */
        status = general_ball(general, x, man, exp, dps_obj, text, most, exact);
        goto done;
    }
    if (as_ll(PyTuple_GET_ITEM(sc, 2), &unit) < 0 || as_ll(PyTuple_GET_ITEM(sc, 3), &shift) < 0
        || as_ll(PyTuple_GET_ITEM(sc, 5), &fix) < 0)
        goto done;
    PyObject *p5 = PyTuple_GET_ITEM(sc, 4), *thr = PyTuple_GET_ITEM(sc, 6);
    PyObject *cut = PyTuple_GET_ITEM(sc, 9), *splito = PyTuple_GET_ITEM(sc, 11);
    PyObject *piece = PyTuple_GET_ITEM(sc, 12), *nines = PyTuple_GET_ITEM(sc, 13);
    PyObject *fewer = PyTuple_GET_ITEM(sc, 14);
    double u = PyFloat_AsDouble(PyTuple_GET_ITEM(sc, 7));
    if (u == -1.0 && PyErr_Occurred())
        goto done;
    /* n = (mag >> (bc - shift) if shift < bc else mag << (shift - bc)) * p5 >> fix */
    count = PyLong_FromLongLong(shift < bc ? bc - shift : shift - bc);
    if (count == NULL)
        goto done;
    t = shift < bc ? PyNumber_Rshift(mag, count) : PyNumber_Lshift(mag, count);
    if (t == NULL)
        goto done;
    t2 = PyNumber_Multiply(t, p5);
    if (t2 == NULL)
        goto done;
    Py_SETREF(count, PyLong_FromLongLong(fix));
    if (count == NULL)
        goto done;
    n = PyNumber_Rshift(t2, count);
    if (n == NULL)
        goto done;
    /* if n < thr: cut, half, split, piece, nines = fewer (one digit fewer; half is read off the
     * digits below) */
    int fewer_digits = PyObject_RichCompareBool(n, thr, Py_LT);
    if (fewer_digits < 0)
        goto done;
    if (fewer_digits) {
        if (!PyTuple_Check(fewer) || PyTuple_GET_SIZE(fewer) != 5) {
            PyErr_SetString(PyExc_TypeError, "a scale's fewer digits are a tuple of 5");
            goto done;
        }
        cut = PyTuple_GET_ITEM(fewer, 0);
        splito = PyTuple_GET_ITEM(fewer, 2);
        piece = PyTuple_GET_ITEM(fewer, 3);
        nines = PyTuple_GET_ITEM(fewer, 4);
    }
    if (as_ll(splito, &split) < 0)
        goto done;
    if (!PyUnicode_Check(piece) || !PyUnicode_Check(nines)) {
        PyErr_SetString(PyExc_TypeError, "a scale's pieces are texts");
        goto done;
    }
    /* D, rem = divmod(n, cut), read off n's decimal digits: cut is 10**k with k = len - dps (n
     * has the scale's count of digits, c or c - 1), D the first dps digits and rem the other k;
     * anything else is the Python loop's */
    digits = PyObject_Str(n);
    if (digits == NULL)
        goto done;
    Py_ssize_t len;
    const char *s = PyUnicode_AsUTF8AndSize(digits, &len);
    if (s == NULL)
        goto done;
    long long k = (long long)len - dps;
    if (k < 1 || k > MAX_CUT || dps < 1 || dps > MAX_DIGITS) {
        status = TO_PYTHON;
        goto done;
    }
    int is_cut = PyObject_RichCompareBool(cut, tens_to[k], Py_EQ);
    if (is_cut <= 0) {
        if (is_cut == 0)
            status = TO_PYTHON;
        goto done;
    }
    char D[MAX_DIGITS];
    memcpy(D, s, (size_t)dps);
    unsigned long long rem = 0;
    for (Py_ssize_t i = dps; i < len; i++)
        rem = 10 * rem + (unsigned long long)(s[i] - '0');
    /* if rem >= half: D += 1; rem = cut - rem (round half up: the first digit cut is 5 or more) */
    int carried = 0;
    if (s[dps] >= '5') {
        rem = pow10_u64[k] - rem;
        Py_ssize_t i = dps - 1;
        while (i >= 0 && D[i] == '9')
            D[i--] = '0';
        if (i >= 0)
            D[i] += 1;
        else  /* if D == tens: a run of nines carried into 10**dps */
            carried = 1;
    }
    /* e = rem * u; if acc < unit: e += float(x.rad()) */
    double e = (double)(long long)rem * u;
    if (acc < unit) {
        Py_CLEAR(t);
        t = call0(m_rad, x, s_rad);
        if (t == NULL)
            goto done;
        double r = PyFloat_AsDouble(t);
        if (r == -1.0 && PyErr_Occurred())
            goto done;
        e += r;
    }
    /* if e > most: most = e; if u > wide: wide = u */
    if (e > *most)
        *most = e;
    if (u > *wide)
        *wide = u;
    /* the text: nines where carried, else the digits, the point and the piece; the sign */
    if (carried) {
        if (negative) {
            *text = PyUnicode_FromFormat("-%U", nines);
        }
        else {
            Py_INCREF(nines);
            *text = nines;
        }
    }
    else {
        *text = write_text(D, (Py_ssize_t)dps, split, piece, negative);
    }
    if (*text != NULL)
        status = WRITTEN;
done:
    Py_XDECREF(mid);
    Py_XDECREF(me);
    Py_XDECREF(man);
    Py_XDECREF(mag);
    Py_XDECREF(key);
    Py_XDECREF(count);
    Py_XDECREF(t);
    Py_XDECREF(t2);
    Py_XDECREF(n);
    Py_XDECREF(digits);
    return status;
}

/* verify.result._bound_between: the text (two digits, rounded up) of a number known to lie
 * between least and most, or NULL with no error set where those do not decide it */
static PyObject *
bound_between(double least, double most, PyObject *tens)
{
    if (!(1e-280 < least && most < 1e280))
        return NULL;
    most *= 1 + 1e-12;
    least *= 1 - 1e-12;
    long e = (long)floor(log10(most));
    double t = PyFloat_AS_DOUBLE(PyTuple_GET_ITEM(tens, 1 - e + 300));
    double q = most * t;
    if (q < 10) {
        e -= 1;
        t = PyFloat_AS_DOUBLE(PyTuple_GET_ITEM(tens, 1 - e + 300));
        q = most * t;
    }
    else if (q >= 100) {
        e += 1;
        t = PyFloat_AS_DOUBLE(PyTuple_GET_ITEM(tens, 1 - e + 300));
        q = most * t;
    }
    double c = ceil(q);
    if (!(c > 10 && least * t > c - 1))
        return NULL;
    if (c >= 100)
        return PyUnicode_FromFormat("1.0e%ld", e + 1);
    long ci = (long)c;
    return PyUnicode_FromFormat("%ld.%lde%ld", ci / 10, ci % 10, e);
}

static PyObject *
row(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    (void)self;
    if (nargs != 5) {
        PyErr_SetString(PyExc_TypeError, "row(balls, scales, tens, general, dps): five arguments");
        return NULL;
    }
    PyObject *scales = args[1], *tens = args[2], *general = args[3], *dps = args[4];
    long long dps_n = PyLong_AsLongLong(dps);
    if (dps_n == -1 && PyErr_Occurred())
        return NULL;
    if (!PyDict_Check(scales) || !PyTuple_Check(tens) || PyTuple_GET_SIZE(tens) != 601) {
        PyErr_SetString(PyExc_TypeError, "row(): scales a dict, tens a tuple of 601 floats");
        return NULL;
    }
    for (Py_ssize_t j = 0; j < 601; j++) {
        if (!PyFloat_CheckExact(PyTuple_GET_ITEM(tens, j))) {
            PyErr_SetString(PyExc_TypeError, "row(): tens a tuple of 601 floats");
            return NULL;
        }
    }
    PyObject *seq = PySequence_Fast(args[0], "row(): balls a sequence");
    if (seq == NULL)
        return NULL;
    Py_ssize_t size = PySequence_Fast_GET_SIZE(seq);
    PyObject **items = PySequence_Fast_ITEMS(seq);
    PyObject *texts = PyTuple_New(size);
    if (texts == NULL) {
        Py_DECREF(seq);
        return NULL;
    }
    /* the largest error lies within 4.2 wide below most and 5.2 wide above */
    double most = 0.0, wide = 0.0;
    int exact = 0;
    for (Py_ssize_t i = 0; i < size; i++) {
        PyObject *text;
        int status = one_ball(items[i], scales, general, dps, dps_n, &text, &most, &wide, &exact);
        if (status != WRITTEN) {
            Py_DECREF(texts);
            Py_DECREF(seq);
            if (status == FAILED)
                return NULL;
            Py_RETURN_NONE;
        }
        PyTuple_SET_ITEM(texts, i, text);
    }
    Py_DECREF(seq);
    /* _row_bound: in doubles where they decide it, else None (in integers) */
    PyObject *bound = NULL;
    if (!(exact || most < 8.4 * wide)) {
        bound = bound_between(most - 4.2 * wide, most + 5.2 * wide, tens);
        if (bound == NULL && PyErr_Occurred()) {
            Py_DECREF(texts);
            return NULL;
        }
    }
    if (bound == NULL) {
        Py_INCREF(Py_None);
        bound = Py_None;
    }
    return Py_BuildValue("(NN)", texts, bound);
}

static PyMethodDef methods[] = {
    {"row", (PyCFunction)(void (*)(void))row, METH_FASTCALL,
     "row(balls, scales, tens, general, dps) -> (texts, bound or None), or None for the Python "
     "loop (verify.result._row_of_balls)."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    .m_name = "_digits",
    .m_doc = "The digits of a row of balls, compiled (verify.result._row_of_balls's loop).",
    .m_size = -1,
    .m_methods = methods,
};

PyMODINIT_FUNC
PyInit__digits(void)
{
    s_mid = PyUnicode_InternFromString("mid");
    s_man_exp = PyUnicode_InternFromString("man_exp");
    s_rel_accuracy_bits = PyUnicode_InternFromString("rel_accuracy_bits");
    s_rad = PyUnicode_InternFromString("rad");
    if (!s_mid || !s_man_exp || !s_rel_accuracy_bits || !s_rad)
        return NULL;
    unsigned long long p = 1;
    for (int k = 0; k <= MAX_CUT; k++) {
        pow10_u64[k] = p;
        tens_to[k] = PyLong_FromUnsignedLongLong(p);
        if (tens_to[k] == NULL)
            return NULL;
        p *= 10;
    }
    return PyModule_Create(&module);
}
