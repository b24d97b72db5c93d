/* One-state entry point for CPython: any function of a generated unit, called on NumPy arrays.
 *
 * cffi costs about 1 us per call (a buffer conversion per array); this extension reads the
 * NumPy arrays' data pointers directly and calls the generated C, so a law is a few hundred
 * nanoseconds from Python. It does not contain the generated code: it calls the functions of the
 * unit's cffi module through their addresses, given at bind time, so a unit is compiled once.
 * It is compiled and cached by hybrid/native/loader.py, which writes before this file, from the unit's
 * manifest:
 *
 *   static int adapt_K(hybrid_fn fn, const double *const *in, double tol, double *const *out) { ... }
 *                                         one per function: calls fn, cast to the function's
 *                                         prototype, with its arguments in order
 *   #define HYBRID_FAST_FUNCTIONS ...     {"symbol", adapt_K, n_in, n_out, {in sizes}, {out rows, cols}}, ...
 *   #define HYBRID_FAST_MAX_OUT ...       the largest total output size
 *   #define HYBRID_FAST_MAX_ARGS ...      the most inputs (or outputs) a function may have
 *   #define HYBRID_MODULE ...             the module's name (its cache key)
 *
 * bind(symbol, address, n_state, params, singular_tol) fixes the function's address (from the cffi
 * module) and its trailing inputs (the parameters);
 * call(binding, which, *states) takes the leading ones and returns new arrays;
 * call_into(binding, outs, *states) writes the outputs into the caller's arrays instead. Anything off the fast path (lists,
 * other dtypes, strided or byte-swapped arrays, N states, a non-OK status) returns None, and
 * the Python caller takes its checked path, which raises the descriptive error. A binding is
 * read-only once made, so concurrent calls from threads are safe.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>
#include <stdlib.h>
#include <string.h>

#define HYBRID_STR_(x) #x
#define HYBRID_STR(x) HYBRID_STR_(x)
#define HYBRID_INIT_(name) PyInit_##name
#define HYBRID_INIT(name) HYBRID_INIT_(name)

typedef void (*hybrid_fn)(void);
typedef int (*adapter)(hybrid_fn fn, const double *const *in, double tol, double *const *out);

typedef struct {
    const char *symbol;
    adapter fn;
    int n_in, n_out;
    Py_ssize_t in_size[HYBRID_FAST_MAX_ARGS];
    npy_intp out_shape[HYBRID_FAST_MAX_ARGS][2]; /* rows, cols (cols 0: a vector) */
} fast_function;

static const fast_function FUNCTIONS[] = {HYBRID_FAST_FUNCTIONS};

/* a function with its parameters (the inputs after the state ones) copied at bind time */
typedef struct {
    const fast_function *f;
    hybrid_fn fn;
    int n_state;
    double tol;
    double *params[HYBRID_FAST_MAX_ARGS];
} binding;

static const char CAPSULE[] = "hybrid.fastcall.binding";

static void binding_release(binding *b) {
    int i;
    for (i = 0; i < HYBRID_FAST_MAX_ARGS; ++i) free(b->params[i]);
    free(b);
}

static void binding_free(PyObject *capsule) { binding_release(PyCapsule_GetPointer(capsule, CAPSULE)); }

/* bind(symbol, address, n_state, params, singular_tol) -> capsule */
static PyObject *bind(PyObject *self, PyObject *args) {
    const char *symbol;
    int n_state, i;
    PyObject *params, *address;
    double tol;
    const fast_function *f = NULL;
    size_t k;
    void *where;
    (void)self;
    if (!PyArg_ParseTuple(args, "sO!iO!d", &symbol, &PyLong_Type, &address, &n_state, &PyTuple_Type, &params, &tol))
        return NULL;
    where = PyLong_AsVoidPtr(address);
    if (where == NULL) {
        if (!PyErr_Occurred()) PyErr_SetString(PyExc_ValueError, "fastcall.bind: the function's address is 0");
        return NULL;
    }
    for (k = 0; k < sizeof FUNCTIONS / sizeof FUNCTIONS[0]; ++k) {
        if (strcmp(FUNCTIONS[k].symbol, symbol) == 0) f = &FUNCTIONS[k];
    }
    if (f == NULL) return PyErr_Format(PyExc_ValueError, "fastcall.bind: the unit has no function '%s'", symbol);
    if (n_state < 0 || n_state + PyTuple_GET_SIZE(params) != f->n_in)
        return PyErr_Format(PyExc_ValueError, "fastcall.bind: %s takes %d inputs", symbol, f->n_in);
    binding *b = calloc(1, sizeof *b);
    if (b == NULL) return PyErr_NoMemory();
    b->f = f;
    b->fn = (hybrid_fn)(size_t)where; /* a function's address, as cffi gives it */
    b->n_state = n_state;
    b->tol = tol;
    for (i = n_state; i < f->n_in; ++i) {
        PyArrayObject *arr = (PyArrayObject *)PyArray_FROMANY(PyTuple_GET_ITEM(params, i - n_state), NPY_DOUBLE,
                                                              1, 1, NPY_ARRAY_CARRAY_RO);
        Py_ssize_t n = f->in_size[i];
        if (arr == NULL || PyArray_DIM(arr, 0) != n) {
            Py_XDECREF(arr);
            binding_release(b);
            if (!PyErr_Occurred()) PyErr_Format(PyExc_ValueError, "fastcall.bind: input %d needs %zd values", i, n);
            return NULL;
        }
        b->params[i] = malloc((size_t)(n > 0 ? n : 1) * sizeof(double));
        if (b->params[i] != NULL) memcpy(b->params[i], PyArray_DATA(arr), (size_t)n * sizeof(double));
        Py_DECREF(arr);
        if (b->params[i] == NULL) {
            binding_release(b);
            return PyErr_NoMemory();
        }
    }
    PyObject *capsule = PyCapsule_New(b, CAPSULE, binding_free);
    if (capsule == NULL) binding_release(b);
    return capsule;
}

/* the data of a 1-D C-contiguous aligned native float64 array of n values, else NULL */
static const double *vector(PyObject *obj, Py_ssize_t n) {
    if (!PyArray_Check(obj)) return NULL;
    PyArrayObject *arr = (PyArrayObject *)obj;
    if (PyArray_NDIM(arr) != 1 || PyArray_DIM(arr, 0) != n || PyArray_TYPE(arr) != NPY_DOUBLE
        || !PyArray_ISCARRAY_RO(arr) || PyArray_ISBYTESWAPPED(arr))
        return NULL;
    return (const double *)PyArray_DATA(arr);
}

static PyObject *new_output(const fast_function *f, int k, const double *data) {
    npy_intp dims[2] = {f->out_shape[k][0], f->out_shape[k][1]};
    PyObject *out = PyArray_SimpleNew(dims[1] ? 2 : 1, dims, NPY_DOUBLE);
    if (out != NULL) memcpy(PyArray_DATA((PyArrayObject *)out), data, (size_t)PyArray_SIZE((PyArrayObject *)out) * sizeof(double));
    return out;
}

/* call(binding, which, *states) -> output `which`, a tuple of all (which = -1), or None */
static PyObject *call(PyObject *self, PyObject *const *args, Py_ssize_t nargs) {
    const double *in[HYBRID_FAST_MAX_ARGS];
    double buf[HYBRID_FAST_MAX_OUT];
    double *out[HYBRID_FAST_MAX_ARGS];
    int i, k;
    Py_ssize_t offset = 0;
    (void)self;
    if (nargs < 2) {
        PyErr_SetString(PyExc_TypeError, "fastcall.call takes (binding, which, *states)");
        return NULL;
    }
    const binding *b = PyCapsule_GetPointer(args[0], CAPSULE);
    if (b == NULL) return NULL;
    const fast_function *f = b->f;
    long which = PyLong_AsLong(args[1]);
    if (which == -1 && PyErr_Occurred()) return NULL;
    if (nargs - 2 != b->n_state || which < -1 || which >= f->n_out) Py_RETURN_NONE;
    for (i = 0; i < b->n_state; ++i) {
        in[i] = vector(args[2 + i], f->in_size[i]);
        if (in[i] == NULL) Py_RETURN_NONE;
    }
    for (i = b->n_state; i < f->n_in; ++i) in[i] = b->params[i];
    for (k = 0; k < f->n_out; ++k) {
        out[k] = buf + offset;
        offset += f->out_shape[k][0] * (f->out_shape[k][1] ? f->out_shape[k][1] : 1);
    }
    if (f->fn(b->fn, in, b->tol, out) != 0) Py_RETURN_NONE;
    if (which >= 0) return new_output(f, (int)which, out[which]);
    PyObject *all = PyTuple_New(f->n_out);
    if (all == NULL) return NULL;
    for (k = 0; k < f->n_out; ++k) {
        PyObject *o = new_output(f, k, out[k]);
        if (o == NULL) {
            Py_DECREF(all);
            return NULL;
        }
        PyTuple_SET_ITEM(all, k, o);
    }
    return all;
}

/* the data of a writable 1-D C-contiguous aligned native float64 array of n values, else NULL */
static double *writable(PyObject *obj, Py_ssize_t n) {
    if (!PyArray_Check(obj) || !PyArray_ISWRITEABLE((PyArrayObject *)obj)) return NULL;
    return (double *)vector(obj, n);
}

/* call_into(binding, outs, *states) -> True (outputs written into the arrays of the list or tuple
 * outs), or None off the fast path (outputs untouched when the function failed) */
static PyObject *call_into(PyObject *self, PyObject *const *args, Py_ssize_t nargs) {
    const double *in[HYBRID_FAST_MAX_ARGS];
    double buf[HYBRID_FAST_MAX_OUT];
    double *out[HYBRID_FAST_MAX_ARGS], *dest[HYBRID_FAST_MAX_ARGS];
    int i, k;
    Py_ssize_t offset = 0;
    (void)self;
    if (nargs < 2 || !(PyList_Check(args[1]) || PyTuple_Check(args[1]))) {
        PyErr_SetString(PyExc_TypeError, "fastcall.call_into takes (binding, outs, *states)");
        return NULL;
    }
    const binding *b = PyCapsule_GetPointer(args[0], CAPSULE);
    if (b == NULL) return NULL;
    const fast_function *f = b->f;
    PyObject *outs = args[1];
    if (nargs - 2 != b->n_state || PySequence_Fast_GET_SIZE(outs) != f->n_out) Py_RETURN_NONE;
    for (i = 0; i < b->n_state; ++i) {
        in[i] = vector(args[2 + i], f->in_size[i]);
        if (in[i] == NULL) Py_RETURN_NONE;
    }
    for (i = b->n_state; i < f->n_in; ++i) in[i] = b->params[i];
    for (k = 0; k < f->n_out; ++k) {
        Py_ssize_t size = f->out_shape[k][0] * (f->out_shape[k][1] ? f->out_shape[k][1] : 1);
        dest[k] = writable(PySequence_Fast_GET_ITEM(outs, k), size);
        if (dest[k] == NULL) Py_RETURN_NONE;
        out[k] = buf + offset;
        offset += size;
    }
    /* computed into a local buffer first: an output array may also be an input */
    if (f->fn(b->fn, in, b->tol, out) != 0) Py_RETURN_NONE;
    for (k = 0; k < f->n_out; ++k) {
        Py_ssize_t size = f->out_shape[k][0] * (f->out_shape[k][1] ? f->out_shape[k][1] : 1);
        memcpy(dest[k], out[k], (size_t)size * sizeof(double));
    }
    Py_RETURN_TRUE;
}

static PyMethodDef methods[] = {
    {"bind", bind, METH_VARARGS, "bind(symbol, address, n_state, params, singular_tol) -> binding"},
    {"call", (PyCFunction)(void (*)(void))call, METH_FASTCALL,
     "call(binding, which, *states) -> output which, all outputs (which=-1), or None off the fast path"},
    {"call_into", (PyCFunction)(void (*)(void))call_into, METH_FASTCALL,
     "call_into(binding, outs, *states) -> True (outputs written into outs), or None off the fast path"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, HYBRID_STR(HYBRID_MODULE),
                                    "one-state calls of a generated unit for CPython", -1, methods,
                                    NULL, NULL, NULL, NULL};

PyMODINIT_FUNC HYBRID_INIT(HYBRID_MODULE)(void) {
    import_array();
    return PyModule_Create(&module);
}
