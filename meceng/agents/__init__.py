"""The agent: what a model is asked (``prompts``), how its answers are read (``parsing``), the two
LLM steps of a task (``steps``), the tool-calling loop (``loop``) with its tools (``toolbox``,
``tool_schemas``, ``energy``) and its eyes (``inspect``). Talking to servers is ``meceng.llm``'s
concern, the components it documents ``meceng.catalog``'s."""
