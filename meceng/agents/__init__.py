"""The agent: what a model is asked (``prompts``), how its answers are read (``parsing``), the two
LLM steps of a task (``steps``), the tool-calling loop (``loop``) with its tools (``toolbox``,
``tool_schemas``, ``energy``). Talking to servers is ``meceng.llm``'s concern, the components it
documents ``meceng.catalog``'s, what a program built (its tools' answers) ``meceng.inspect``'s."""
